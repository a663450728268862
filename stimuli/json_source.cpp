#include "stimuli/json_source.hpp"

#include "common/number_format.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <iterator>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace signstim::stimuli {
namespace {

using nlohmann::json;

// A const char* that also records, in `*furthest`, how far it has been advanced: the input of
// the SAX parser, so that each event knows the byte it was raised at.
class TrackingIterator {
public:
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    TrackingIterator() = default;
    TrackingIterator(const char* at, const char** furthest) : at_(at), furthest_(furthest) {}
    reference operator*() const { return *at_; }
    TrackingIterator& operator++() {
        ++at_;
        if (furthest_) *furthest_ = at_;
        return *this;
    }
    TrackingIterator operator++(int) {
        TrackingIterator before = *this;
        ++*this;
        return before;
    }
    bool operator==(const TrackingIterator& other) const { return at_ == other.at_; }
    bool operator!=(const TrackingIterator& other) const { return at_ != other.at_; }

private:
    const char* at_ = nullptr;
    const char** furthest_ = nullptr;
};

std::string withoutExceptionPrefix(std::string what) {
    if (const std::size_t bracket = what.find("] "); what.rfind("[json.exception", 0) == 0 && bracket != std::string::npos)
        what.erase(0, bracket + 2);
    return what;
}

// Builds the json value like nlohmann's own DOM parser, and records the line of every value by
// its JSON pointer; refuses a key that appears twice in one object.
class LineRecordingBuilder {
public:
    using number_integer_t = json::number_integer_t;
    using number_unsigned_t = json::number_unsigned_t;
    using number_float_t = json::number_float_t;
    using string_t = json::string_t;
    using binary_t = json::binary_t;

    LineRecordingBuilder(JsonSource& source, const char** furthest)
        : source_(source), begin_(source.text.data()), furthest_(furthest) {
        for (std::size_t i = 0; i < source.text.size(); ++i)
            if (source.text[i] == '\n') newlines_.push_back(i);
    }

    bool null() { return add(json(nullptr)); }
    bool boolean(bool value) { return add(json(value)); }
    bool number_integer(number_integer_t value) { return add(json(value)); }
    bool number_unsigned(number_unsigned_t value) { return add(json(value)); }
    bool number_float(number_float_t value, const string_t&) { return add(json(value)); }
    bool string(string_t& value) { return add(json(std::move(value))); }
    bool binary(binary_t& value) { return add(json(std::move(value))); }
    bool start_object(std::size_t) { return open(json::object()); }
    bool start_array(std::size_t) { return open(json::array()); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }

    bool key(string_t& name) {
        Frame& frame = stack_.back();
        const int line = lineOfLastToken();
        const auto [existing, inserted] = frame.keyLines.emplace(name, line);
        const std::string pointer = frame.pointer + "/" + jsonPointerToken(name);
        if (!inserted)
            throw InputError(source_.file, line, pointer,
                             "duplicate key '" + name + "' (first on line " + std::to_string(existing->second) +
                                 "; a JSON object may give each key once)");
        frame.pendingKey = name;
        source_.lines[pointer] = line;
        return true;
    }

    bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& error) {
        const int line = lineOfOffset(std::min(position, source_.text.size()));
        std::string field;
        if (!stack_.empty()) {
            const Frame& frame = stack_.back();
            field = frame.container->is_object() && !frame.pendingKey.empty()
                        ? frame.pointer + "/" + jsonPointerToken(frame.pendingKey)
                        : frame.pointer;
        }
        std::string message = "not valid JSON: " + withoutExceptionPrefix(error.what());
        if (error.id == 406) message += " (numbers must fit a double: at most about 1.8e308 in size)";
        throw InputError(source_.file, line, field, message);
    }

private:
    struct Frame {
        json* container = nullptr;
        std::string pointer;
        std::map<std::string, int> keyLines;
        std::string pendingKey;
    };

    // Line of the last token read: the parser may have read one character past a number, so
    // step back over white space to the token's last character.
    int lineOfLastToken() const { return lineOfOffset(static_cast<std::size_t>(*furthest_ - begin_)); }
    int lineOfOffset(std::size_t consumed) const {
        while (consumed > 0 && std::string_view(" \t\r\n").find(source_.text[consumed - 1]) != std::string_view::npos)
            --consumed;
        const std::size_t last = consumed == 0 ? 0 : consumed - 1;
        return 1 + static_cast<int>(std::lower_bound(newlines_.begin(), newlines_.end(), last) - newlines_.begin());
    }

    // Where the next value goes, its pointer, and records its line (array elements and the
    // root; an object member has its key's line).
    std::pair<json*, std::string> place(json&& value) {
        if (stack_.empty()) {
            source_.root = std::move(value);
            source_.lines[""] = lineOfLastToken();
            return {&source_.root, ""};
        }
        Frame& frame = stack_.back();
        if (frame.container->is_object()) {
            const std::string pointer = frame.pointer + "/" + jsonPointerToken(frame.pendingKey);
            json& slot = (*frame.container)[frame.pendingKey];
            slot = std::move(value);
            frame.pendingKey.clear();
            return {&slot, pointer};
        }
        const std::string pointer = frame.pointer + "/" + std::to_string(frame.container->size());
        frame.container->push_back(std::move(value));
        source_.lines[pointer] = lineOfLastToken();
        return {&frame.container->back(), pointer};
    }
    bool add(json&& value) {
        place(std::move(value));
        return true;
    }
    bool open(json&& container) {
        auto [slot, pointer] = place(std::move(container));
        stack_.push_back({slot, pointer, {}, {}});
        return true;
    }
    bool close() {
        stack_.pop_back();
        return true;
    }

    JsonSource& source_;
    const char* begin_;
    const char** furthest_;
    std::vector<std::size_t> newlines_;
    std::vector<Frame> stack_;
};

const char* kindOfFile(mode_t mode) {
    if (S_ISDIR(mode)) return "is a directory";
    if (S_ISFIFO(mode)) return "is a FIFO (named pipe)";
    if (S_ISCHR(mode)) return "is a character device";
    if (S_ISBLK(mode)) return "is a block device";
    if (S_ISSOCK(mode)) return "is a socket";
    return "is not a regular file";
}

}  // namespace

std::string jsonPointerToken(const std::string& key) {
    std::string token;
    for (char c : key) {
        if (c == '~') token += "~0";
        else if (c == '/') token += "~1";
        else token += c;
    }
    return token;
}

std::string_view withoutByteOrderMark(std::string_view text) {
    if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    return text;
}

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

// Where `anchor` occurs in `text` at or after `from`, a space in the anchor matching any run of
// white space, also none ("\"name\": \"A\"" finds "\"name\":\"A\"" of a compact file);
// `end` is set past the match. npos when absent.
std::size_t findLoosely(const std::string& text, const std::string& anchor, std::size_t from, std::size_t& end) {
    std::vector<std::string> pieces;
    std::size_t start = 0;
    while (start <= anchor.size()) {
        const std::size_t space = anchor.find(' ', start);
        const std::string piece = anchor.substr(start, space == std::string::npos ? std::string::npos : space - start);
        if (!piece.empty()) pieces.push_back(piece);
        if (space == std::string::npos) break;
        start = space + 1;
    }
    if (pieces.empty()) return std::string::npos;
    for (std::size_t at = text.find(pieces[0], from); at != std::string::npos; at = text.find(pieces[0], at + 1)) {
        std::size_t position = at + pieces[0].size();
        bool matched = true;
        for (std::size_t i = 1; i < pieces.size() && matched; ++i) {
            while (position < text.size() && isSpace(text[position])) ++position;
            matched = text.compare(position, pieces[i].size(), pieces[i]) == 0;
            position += pieces[i].size();
        }
        if (matched) {
            end = position;
            return at;
        }
    }
    return std::string::npos;
}

}  // namespace

int JsonSource::lineOf(const std::vector<std::string>& anchors) const {
    std::size_t position = 0;
    std::size_t found = std::string::npos;
    for (const std::string& anchor : anchors) {
        std::size_t end = 0;
        const std::size_t at = findLoosely(text, anchor, position, end);
        if (at == std::string::npos) break;
        found = at;
        position = end;
    }
    if (found == std::string::npos) return 0;
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(found), '\n'));
}

int JsonSource::lineAt(const std::string& pointer) const {
    std::string at = pointer;
    while (true) {
        if (const auto it = lines.find(at); it != lines.end()) return it->second;
        if (at.empty()) return 0;
        at.erase(at.rfind('/') == std::string::npos ? 0 : at.rfind('/'));
    }
}

void JsonSource::fail(const std::vector<std::string>& anchors, const std::string& field,
                      const std::string& message) const {
    const bool isPointer = !field.empty() && field.front() == '/';
    const int line = isPointer && !lines.empty() ? lineAt(field) : lineOf(anchors);
    throw InputError(file, line, field, message);
}

void JsonSource::failAt(const std::string& pointer, const std::string& message) const {
    throw InputError(file, lineAt(pointer), pointer, message);
}

double JsonSource::number(const nlohmann::json& value, const std::string& pointer, const NumberRange& range) const {
    if (!value.is_number()) failAt(pointer, std::string("expected a number, got ") + value.type_name());
    const double result = value.get<double>();
    if (!range.contains(result)) failAt(pointer, rangeMessage(range.minimum, range.maximum, range.unit, result));
    return result;
}

void JsonSource::checkFormat(const std::string& format, int version) const {
    if (!root.is_object()) return;
    if (const auto it = root.find("format"); it != root.end() && *it != format)
        failAt("/format", "expected \"" + format + "\", got " + it->dump() + " (a file of another kind?)");
    if (const auto it = root.find("version"); it != root.end() && !(it->is_number_integer() && *it == version))
        failAt("/version", "expected " + std::to_string(version) + ", got " + it->dump() + " (this signstim reads version " +
                               std::to_string(version) + " files)");
}

void checkInRange(double value, const NumberRange& range, const std::string& file, int line, const std::string& field) {
    if (!range.contains(value)) throw InputError(file, line, field, rangeMessage(range.minimum, range.maximum, range.unit, value));
}

std::string readTextFile(const std::filesystem::path& path) {
    const std::string name = path.string();
    struct stat info {};
    if (::stat(path.c_str(), &info) != 0) {
        const int error = errno;
        if (error == ENOENT || error == ENOTDIR || name.empty()) throw InputError(name, 0, "", "no such file");
        throw IoError(name, "cannot read", error);
    }
    if (!S_ISREG(info.st_mode)) throw InputError(name, 0, "", std::string(kindOfFile(info.st_mode)) + ", not a regular file");
    // O_NONBLOCK: should the path have become a FIFO since the stat, opening it cannot hang.
    const int descriptor = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (descriptor < 0) {
        const int error = errno;
        if (error == ENOENT) throw InputError(name, 0, "", "no such file");
        throw IoError(name, "cannot read", error);
    }
    std::string text;
    struct stat opened {};
    if (::fstat(descriptor, &opened) != 0 || !S_ISREG(opened.st_mode)) {
        ::close(descriptor);
        throw InputError(name, 0, "", std::string(kindOfFile(opened.st_mode)) + ", not a regular file");
    }
    char buffer[65536];
    while (true) {
        const ssize_t count = ::read(descriptor, buffer, sizeof buffer);
        if (count < 0) {
            const int error = errno;
            if (error == EINTR) continue;
            ::close(descriptor);
            throw IoError(name, "cannot read", error);
        }
        if (count == 0) break;
        text.append(buffer, static_cast<std::size_t>(count));
    }
    ::close(descriptor);
    return text;
}

JsonSource parseJsonText(std::string text, std::string fileName) {
    JsonSource source{std::move(fileName), std::string(withoutByteOrderMark(text)), {}, {}};
    const char* furthest = source.text.data();
    LineRecordingBuilder builder(source, &furthest);
    const TrackingIterator first(source.text.data(), &furthest);
    const TrackingIterator last(source.text.data() + source.text.size(), nullptr);
    try {
        json::sax_parse(first, last, &builder);
    } catch (const nlohmann::json::exception& e) {
        // Not raised through parse_error (should not happen); still the user's file.
        throw InputError(source.file, 0, "", "not valid JSON: " + withoutExceptionPrefix(e.what()));
    }
    return source;
}

JsonSource readJsonFile(const std::filesystem::path& path) { return parseJsonText(readTextFile(path), path.string()); }

}  // namespace signstim::stimuli
