#pragma once
// Reading JSON data files with errors that name the file, the line and the field.
// nlohmann::json keeps no line numbers, so the line of a field is found by scanning the text
// for the path's keys in order (an approximation that is exact for files written one field
// per line, as ours are); parse errors convert their byte offset to a line.
#include "common/error.hpp"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace signstim::stimuli {

struct JsonSource {
    std::string file;  // as given, for messages
    std::string text;
    nlohmann::json root;

    // Line (1-based) of the last of `anchors`, each searched after the previous one; anchors
    // are raw text such as "\"ASK\"" or "\"position\"". 0 when not found.
    int lineOf(const std::vector<std::string>& anchors) const;

    [[noreturn]] void fail(const std::vector<std::string>& anchors, const std::string& field,
                           const std::string& message) const;
};

// Reads and parses; throws InputError (missing file, parse error with its line).
JsonSource readJsonFile(const std::filesystem::path& path);
JsonSource parseJsonText(std::string text, std::string fileName);

std::string readTextFile(const std::filesystem::path& path);  // throws InputError

}  // namespace signstim::stimuli
