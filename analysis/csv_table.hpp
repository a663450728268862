#pragma once
// Comma-separated values as experiment software writes them (RFC 4180): a header row, then
// records; fields in double quotes may hold commas, doubled quotes and line breaks; CRLF or LF
// line ends; a UTF-8 byte-order mark (Excel's) is skipped. Blank lines are skipped. Lines that
// start with '#' before the header are comments (signstim's synthetic files say SYNTHETIC
// there). Every record keeps the line it starts on, for messages naming file:line:column.
#include "common/input_limits.hpp"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace signstim::analysis {

struct CsvRecord {
    int line = 0;  // 1-based line of the record's first character
    std::vector<std::string> fields;
};

struct CsvTable {
    std::string file;                   // as given, for messages
    std::vector<std::string> comments;  // the text after '#' of each comment line before the header
    std::vector<std::string> header;
    int headerLine = 0;
    std::vector<CsvRecord> records;     // every record has header.size() fields (checked)
};

// Throws InputError naming `file` and the line: an unterminated quote, text after a closing
// quote, a record with more or fewer fields than the header, a duplicate or empty column
// name, no header, more than `maxRecords` records (refused at the first record too many, before
// the rest is read: docs/errors.md, Limits).
CsvTable parseCsv(std::string_view text, const std::string& file, std::size_t maxRecords = limits::kResultRows);

}  // namespace signstim::analysis
