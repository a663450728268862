#pragma once
// Reading JSON data files with errors that name the file, the line and the field.
// The text is parsed through nlohmann's SAX interface with an input that tells how far the
// parser has read, so every value's line is known by its JSON pointer ("/verbs/0/citation/
// right/1/time" -> line 23), duplicate keys are refused naming both lines, and every parse
// error (syntax, a number too large for a double) is an InputError with its line.
// Older readers still name places by text anchors (lineOf), an approximation that is exact
// for files written one field per line; fail() prefers the pointer's line when the field is a
// JSON pointer.
#include "common/error.hpp"
#include "stimuli/number_ranges.hpp"

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace signstim::stimuli {

struct JsonSource {
    std::string file;  // as given, for messages
    std::string text;
    nlohmann::json root;
    // Line (1-based) of each value by JSON pointer; for an object member, the line of its key.
    std::map<std::string, int> lines;

    // Line (1-based) of the last of `anchors`, each searched after the previous one; anchors
    // are raw text such as "\"ASK\"" or "\"position\"". 0 when not found.
    int lineOf(const std::vector<std::string>& anchors) const;
    // Line of the value at `pointer`, else of its nearest enclosing value; 0 when unknown.
    int lineAt(const std::string& pointer) const;

    // The line is that of `field` when it is a JSON pointer ("/a/0/b"), else of `anchors`.
    [[noreturn]] void fail(const std::vector<std::string>& anchors, const std::string& field,
                           const std::string& message) const;
    [[noreturn]] void failAt(const std::string& pointer, const std::string& message) const;

    // The number at `pointer` (`value` is the value there), refused unless finite and in
    // `range`, with the range in the message.
    double number(const nlohmann::json& value, const std::string& pointer, const NumberRange& range) const;

    // The top-level "format" and "version" fields, where present, must be `format` and the
    // integer `version` (a file of another kind or a newer version is refused, not misread).
    void checkFormat(const std::string& format, int version) const;
};

// Reads and parses; throws InputError (missing file, not a regular file, parse error or
// duplicate key with its line) or IoError (the system refused the read).
JsonSource readJsonFile(const std::filesystem::path& path);
JsonSource parseJsonText(std::string text, std::string fileName);

// The whole file. Refuses, as InputError (exit 2), a missing file ("no such file") and anything
// that is not a regular file ("is a directory", "is a FIFO", "is a character device"), before
// opening it, so a FIFO without a writer cannot hang the reader; a read the system refuses
// (permission, I/O error) is IoError (exit 3).
std::string readTextFile(const std::filesystem::path& path);

// `text` without a leading UTF-8 byte-order mark (what Excel and some editors write).
std::string_view withoutByteOrderMark(std::string_view text);

// "a~1b" for the key "a/b" (RFC 6901).
std::string jsonPointerToken(const std::string& key);

// Runs `read` (a reader of `source`), turning any nlohmann exception it lets escape (a value
// of an unexpected type met by .get<>() or .value()) into an InputError naming the file.
template <class Read>
decltype(auto) withJsonErrors(const JsonSource& source, Read&& read) {
    try {
        return std::forward<Read>(read)();
    } catch (const nlohmann::json::exception& e) {
        std::string what = e.what();
        if (const std::size_t bracket = what.find("] "); what.rfind("[json.exception", 0) == 0 && bracket != std::string::npos)
            what.erase(0, bracket + 2);
        throw InputError(source.file, 0, "", "unexpected JSON value: " + what);
    }
}

}  // namespace signstim::stimuli
