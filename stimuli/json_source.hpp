#pragma once
// Reading JSON data files with errors that name the file, the line and the field.
// The text is parsed through nlohmann's SAX interface with an input that tells how far the
// parser has read, so every value's place in the text is recorded (a compact index: three
// 32-bit numbers a value, by position in the document), and the line of a JSON pointer
// ("/verbs/0/citation/right/1/time" -> line 23) is counted from that offset when asked for.
// Duplicate keys are refused naming both lines; every parse error (syntax, a number too large
// for a double) is an InputError with its line. Bounded input (docs/errors.md, Limits): a file
// over its size limit is refused before it is parsed, nesting deeper than limits::kJsonDepth
// when it is met, and a string or key holding a control character (NUL, ESC...; tab and line
// break are allowed) with its line and field, so no such byte reaches a CSV, a page or a message.
// Lines come from the parser's offsets (lineAt, one way). The text search by anchors (lineOf)
// is left only as fail()'s fallback for readers whose fields are not JSON pointers
// (handshapes.json's "handshapes[B].bend", sensor files' "digits.index"): an approximation,
// exact for files written one field per line.
#include "common/error.hpp"
#include "common/input_limits.hpp"
#include "stimuli/number_ranges.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace signstim::stimuli {

// Where each value of a parsed document starts in its text, in document order (the root is
// value 0); an object member's place is that of its key. Memory: 12 bytes a value plus 4 bytes
// per 4 KiB of text, never a string per value.
struct JsonValueIndex {
    std::vector<std::uint32_t> offset;      // byte of the value's (or member's key's) last character
    std::vector<std::uint32_t> firstChild;  // containers: where their values start in `children`
    std::vector<std::uint32_t> children;    // each container's values; an object's in key order
    std::vector<std::uint32_t> blockLines;  // newlines before each 4 KiB block of the text

    bool empty() const { return offset.empty(); }
};

struct JsonSource {
    std::string file;  // as given, for messages
    std::string text;
    nlohmann::json root;
    JsonValueIndex index;

    // Line (1-based) of the last of `anchors`, each searched after the previous one; anchors
    // are raw text such as "\"ASK\"" or "\"position\"". 0 when not found.
    int lineOf(const std::vector<std::string>& anchors) const;
    // Line of the value at `pointer`, else of its nearest enclosing value; 0 when unknown.
    // For an object member, the line of its key.
    int lineAt(const std::string& pointer) const;
    // Whether the parsed document has a value at `pointer`.
    bool has(const std::string& pointer) const;
    // Line (1-based) of byte `offset` of the text.
    int lineOfOffset(std::size_t offset) const;

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

// Reads and parses; throws InputError (missing file, not a regular file, a file over
// `maxBytes`, parse error, nesting deeper than limits::kJsonDepth, a control character in a
// string, or duplicate key, with its line) or IoError (the system refused the read).
JsonSource readJsonFile(const std::filesystem::path& path, std::size_t maxBytes = limits::kJsonFileBytes);
JsonSource parseJsonText(std::string text, std::string fileName, std::size_t maxBytes = limits::kJsonFileBytes);

// The whole file. Refuses, as InputError (exit 2), a missing file ("no such file") and anything
// that is not a regular file ("is a directory", "is a FIFO", "is a character device"), before
// opening it, so a FIFO without a writer cannot hang the reader, and a file larger than
// `maxBytes` before reading it; a read the system refuses (permission, I/O error) is IoError
// (exit 3).
std::string readTextFile(const std::filesystem::path& path, std::size_t maxBytes = limits::kTextFileBytes);

// The InputError for a file of `bytes` bytes over `maxBytes` (docs/errors.md, Limits).
InputError tooLargeError(const std::string& file, std::size_t bytes, std::size_t maxBytes);

// Where `text` holds a control character (below U+0020 but tab and line feed, or U+007F): its
// byte offset; npos when none. Text fields of every data file are checked with it.
std::size_t findControlCharacter(std::string_view text);
// "U+0000 (NUL)" for the message naming such a character.
std::string describeControlCharacter(char c);

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
