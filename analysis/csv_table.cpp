#include "analysis/csv_table.hpp"

#include "common/error.hpp"

#include <set>

namespace signstim::analysis {

namespace {

class CsvScanner {
public:
    CsvScanner(std::string_view text, const std::string& file) : text_(text), file_(file) {}

    bool atEnd() const { return at_ >= text_.size(); }
    int line() const { return line_; }

    // The rest of the current line (without its end), consumed with it.
    std::string restOfLine() {
        std::string out;
        while (!atEnd() && text_[at_] != '\n' && text_[at_] != '\r') out += text_[at_++];
        skipLineEnd();
        return out;
    }

    bool atBlankLine() const { return !atEnd() && (text_[at_] == '\n' || text_[at_] == '\r'); }
    char peek() const { return text_[at_]; }
    void skipLineEnd() {
        if (!atEnd() && text_[at_] == '\r') ++at_;
        if (!atEnd() && text_[at_] == '\n') ++at_;
        ++line_;
    }

    // One record from here to its line end (quoted fields may span lines).
    std::vector<std::string> record() {
        std::vector<std::string> fields;
        for (;;) {
            fields.push_back(field());
            if (atEnd()) break;
            if (text_[at_] == ',') {
                ++at_;
                continue;
            }
            skipLineEnd();  // '\r' or '\n': field() stops only at these, ',' or the end
            break;
        }
        return fields;
    }

private:
    std::string field() {
        std::string out;
        if (atEnd() || text_[at_] != '"') {
            while (!atEnd() && text_[at_] != ',' && text_[at_] != '\n' && text_[at_] != '\r') {
                if (text_[at_] == '"')
                    throw InputError(file_, line_, "", "a double quote inside an unquoted field: put the field in quotes and double the quote");
                out += text_[at_++];
            }
            return out;
        }
        const int startLine = line_;
        ++at_;
        for (;;) {
            if (atEnd()) throw InputError(file_, startLine, "", "a quoted field is never closed (a missing '\"')");
            const char c = text_[at_++];
            if (c == '"') {
                if (!atEnd() && text_[at_] == '"') {
                    out += '"';
                    ++at_;
                    continue;
                }
                if (!atEnd() && text_[at_] != ',' && text_[at_] != '\n' && text_[at_] != '\r')
                    throw InputError(file_, line_, "", "text after the closing quote of a field");
                return out;
            }
            if (c == '\n') ++line_;
            if (c == '\r' && (atEnd() || text_[at_] != '\n')) ++line_;  // a lone CR ends a line too
            out += c;
        }
    }

    std::string_view text_;
    const std::string& file_;
    std::size_t at_ = 0;
    int line_ = 1;
};

}  // namespace

CsvTable parseCsv(std::string_view text, const std::string& file, std::size_t maxRecords) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    CsvTable table;
    table.file = file;
    CsvScanner scan(text, file);
    // Comments and blank lines before the header.
    while (!scan.atEnd() && (scan.atBlankLine() || scan.peek() == '#')) {
        if (scan.atBlankLine()) {
            scan.skipLineEnd();
            continue;
        }
        std::string comment = scan.restOfLine().substr(1);
        if (!comment.empty() && comment.front() == ' ') comment.erase(0, 1);
        table.comments.push_back(std::move(comment));
    }
    if (scan.atEnd()) throw InputError(file, 0, "", "no header row: the file is empty");
    table.headerLine = scan.line();
    table.header = scan.record();
    std::set<std::string> seen;
    for (std::size_t i = 0; i < table.header.size(); ++i) {
        const std::string& name = table.header[i];
        if (name.empty()) throw InputError(file, table.headerLine, "", "column " + std::to_string(i + 1) + " of the header has no name");
        if (!seen.insert(name).second) throw InputError(file, table.headerLine, name, "this column appears twice in the header");
    }
    while (!scan.atEnd()) {
        if (scan.atBlankLine()) {
            scan.skipLineEnd();
            continue;
        }
        CsvRecord record;
        record.line = scan.line();
        if (table.records.size() == maxRecords)
            throw InputError(file, record.line, "",
                             "more than " + std::to_string(maxRecords) +
                                 " rows; a results file holds one participant's trials (docs/errors.md, Limits)");
        record.fields = scan.record();
        if (record.fields.size() != table.header.size())
            throw InputError(file, record.line, "",
                             "this row has " + std::to_string(record.fields.size()) + " fields, the header " +
                                 std::to_string(table.header.size()) + " (a comma inside a field that is not in quotes?)");
        table.records.push_back(std::move(record));
    }
    return table;
}

}  // namespace signstim::analysis
