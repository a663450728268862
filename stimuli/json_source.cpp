#include "stimuli/json_source.hpp"

#include "common/number_format.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <map>

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

constexpr std::size_t kLineBlock = 4096;  // bytes per entry of JsonValueIndex::blockLines

// nlohmann's parse errors quote the text last read, which for a file of megabytes of white
// space is megabytes long: keep the message one readable line.
std::string shortened(std::string message) {
    constexpr std::size_t kMaximum = 300;
    if (message.size() > kMaximum) message = message.substr(0, kMaximum) + "...'";
    return message;
}

// Builds the json value like nlohmann's own DOM parser and records where every value starts
// (JsonValueIndex); refuses a key that appears twice in one object, nesting deeper than
// limits::kJsonDepth and control characters in strings and keys. The parser itself keeps one
// bit per open container, so nothing here recurses or grows faster than the text.
class IndexingBuilder {
public:
    using number_integer_t = json::number_integer_t;
    using number_unsigned_t = json::number_unsigned_t;
    using number_float_t = json::number_float_t;
    using string_t = json::string_t;
    using binary_t = json::binary_t;

    IndexingBuilder(JsonSource& source, const char** furthest)
        : source_(source), index_(source.index), begin_(source.text.data()), furthest_(furthest) {}

    bool null() { return add(json(nullptr)); }
    bool boolean(bool value) { return add(json(value)); }
    bool number_integer(number_integer_t value) { return add(json(value)); }
    bool number_unsigned(number_unsigned_t value) { return add(json(value)); }
    bool number_float(number_float_t value, const string_t&) { return add(json(value)); }
    bool string(string_t& value) {
        checkText(value, pointerOfNext(), "text");
        return add(json(std::move(value)));
    }
    bool binary(binary_t& value) { return add(json(std::move(value))); }
    bool start_object(std::size_t) { return open(json::object()); }
    bool start_array(std::size_t) { return open(json::array()); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }

    bool key(string_t& name) {
        Frame& frame = stack_.back();
        const std::size_t at = lastTokenOffset();
        const std::string pointer = frame.pointer + "/" + jsonPointerToken(name);
        checkText(name, frame.pointer, "key");
        const std::uint32_t value = static_cast<std::uint32_t>(index_.offset.size());
        const auto [existing, inserted] = frame.members.emplace(name, value);
        if (!inserted)
            throw InputError(source_.file, source_.lineOfOffset(at), pointer,
                             "duplicate key '" + name + "' (first on line " +
                                 std::to_string(source_.lineOfOffset(index_.offset[existing->second])) +
                                 "; a JSON object may give each key once)");
        frame.pendingKey = name;
        // The member's value is the next value recorded; its place is its key's.
        keyOffset_ = at;
        return true;
    }

    bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& error) {
        const int line = source_.lineOfOffset(stepBackOverSpace(std::min(position, source_.text.size())));
        std::string field;
        if (!stack_.empty()) {
            const Frame& frame = stack_.back();
            field = frame.container->is_object() && !frame.pendingKey.empty()
                        ? frame.pointer + "/" + jsonPointerToken(frame.pendingKey)
                        : frame.pointer;
        }
        std::string message = "not valid JSON: " + shortened(withoutExceptionPrefix(error.what()));
        if (error.id == 406) message += " (numbers must fit a double: at most about 1.8e308 in size)";
        throw InputError(source_.file, line, field, message);
    }

private:
    struct Frame {
        json* container = nullptr;
        std::uint32_t value = 0;  // the container's number in JsonValueIndex
        std::string pointer;
        std::map<std::string, std::uint32_t> members;  // objects: key -> value number
        std::vector<std::uint32_t> elements;           // arrays: value numbers in order
        std::string pendingKey;
    };

    // The offset of the last character of the last token read: the parser may have read one
    // character past a number, so step back over white space to the token's last character.
    std::size_t lastTokenOffset() const { return stepBackOverSpace(static_cast<std::size_t>(*furthest_ - begin_)); }
    std::size_t stepBackOverSpace(std::size_t consumed) const {
        while (consumed > 0 && std::string_view(" \t\r\n").find(source_.text[consumed - 1]) != std::string_view::npos)
            --consumed;
        return consumed == 0 ? 0 : consumed - 1;
    }

    std::string pointerOfNext() const {
        if (stack_.empty()) return "";
        const Frame& frame = stack_.back();
        if (frame.container->is_object()) return frame.pointer + "/" + jsonPointerToken(frame.pendingKey);
        return frame.pointer + "/" + std::to_string(frame.container->size());
    }

    void checkText(const std::string& text, const std::string& pointer, const char* what) const {
        const std::size_t at = findControlCharacter(text);
        if (at == std::string::npos) return;
        throw InputError(source_.file, source_.lineOfOffset(lastTokenOffset()), pointer,
                         std::string("a ") + what + " holds the control character " + describeControlCharacter(text[at]) +
                             " at byte " + std::to_string(at + 1) +
                             " (only tab and line break are allowed; remove the invisible character)");
    }

    // Puts the next value in place, records where it starts, and returns it with its number.
    std::pair<json*, std::uint32_t> place(json&& value) {
        const auto number = static_cast<std::uint32_t>(index_.offset.size());
        if (stack_.empty()) {
            source_.root = std::move(value);
            index_.offset.push_back(static_cast<std::uint32_t>(lastTokenOffset()));
            index_.firstChild.push_back(0);
            return {&source_.root, number};
        }
        Frame& frame = stack_.back();
        json* slot = nullptr;
        if (frame.container->is_object()) {
            slot = &(*frame.container)[frame.pendingKey];
            *slot = std::move(value);
            frame.pendingKey.clear();
            index_.offset.push_back(static_cast<std::uint32_t>(keyOffset_));
        } else {
            frame.container->push_back(std::move(value));
            slot = &frame.container->back();
            frame.elements.push_back(number);
            index_.offset.push_back(static_cast<std::uint32_t>(lastTokenOffset()));
        }
        index_.firstChild.push_back(0);
        return {slot, number};
    }
    bool add(json&& value) {
        place(std::move(value));
        return true;
    }
    bool open(json&& container) {
        if (stack_.size() >= limits::kJsonDepth)
            throw InputError(source_.file, source_.lineOfOffset(lastTokenOffset()), pointerOfNext(),
                             "arrays and objects nested more than " + std::to_string(limits::kJsonDepth) +
                                 " deep (docs/errors.md, Limits: no signstim file needs more than 6)");
        const std::string pointer = pointerOfNext();
        const auto [slot, number] = place(std::move(container));
        stack_.push_back({slot, number, pointer, {}, {}, {}});
        return true;
    }
    bool close() {
        Frame& frame = stack_.back();
        index_.firstChild[frame.value] = static_cast<std::uint32_t>(index_.children.size());
        // An object's values in the order of its keys, which is nlohmann's (std::map) order.
        for (const auto& member : frame.members) index_.children.push_back(member.second);
        index_.children.insert(index_.children.end(), frame.elements.begin(), frame.elements.end());
        stack_.pop_back();
        return true;
    }

    JsonSource& source_;
    JsonValueIndex& index_;
    const char* begin_;
    const char** furthest_;
    std::size_t keyOffset_ = 0;
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

namespace {

// The value numbers along `pointer` from the root, as far as the document has them.
std::vector<std::uint32_t> valuesAlong(const JsonSource& source, const std::string& pointer, bool& complete) {
    const JsonValueIndex& index = source.index;
    std::vector<std::uint32_t> path;
    complete = false;
    if (index.empty()) return path;
    path.push_back(0);
    const json* node = &source.root;
    std::size_t at = 0;
    while (at < pointer.size()) {
        if (pointer[at] != '/') return path;
        const std::size_t end = std::min(pointer.find('/', at + 1), pointer.size());
        std::string token;
        for (std::size_t i = at + 1; i < end; ++i) {
            if (pointer[i] == '~' && i + 1 < end && (pointer[i + 1] == '0' || pointer[i + 1] == '1')) {
                token += pointer[++i] == '0' ? '~' : '/';
            } else {
                token += pointer[i];
            }
        }
        at = end;
        std::size_t rank = 0;
        const json* child = nullptr;
        if (node->is_object()) {
            const auto it = node->find(token);
            if (it == node->end()) return path;
            rank = static_cast<std::size_t>(std::distance(node->begin(), it));
            child = &*it;
        } else if (node->is_array()) {
            if (token.empty() || token.size() > 9 || token.find_first_not_of("0123456789") != std::string::npos) return path;
            rank = std::stoul(token);
            if (rank >= node->size()) return path;
            child = &(*node)[rank];
        } else {
            return path;
        }
        // A reader that added members after parsing (operator[] on a missing key) shifts the
        // order: the enclosing value's line is then the best known.
        const std::size_t slot = index.firstChild[path.back()] + rank;
        if (slot >= index.children.size()) return path;
        path.push_back(index.children[slot]);
        node = child;
    }
    complete = true;
    return path;
}

}  // namespace

int JsonSource::lineOfOffset(std::size_t offset) const {
    if (text.empty()) return 1;
    offset = std::min(offset, text.size() - 1);
    const std::size_t block = offset / kLineBlock;
    const std::size_t before = block < index.blockLines.size()
                                   ? index.blockLines[block]
                                   : static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(block * kLineBlock), '\n'));
    const auto first = text.begin() + static_cast<std::ptrdiff_t>(block * kLineBlock);
    return 1 + static_cast<int>(before) + static_cast<int>(std::count(first, text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

int JsonSource::lineAt(const std::string& pointer) const {
    bool complete = false;
    const std::vector<std::uint32_t> path = valuesAlong(*this, pointer, complete);
    if (path.empty()) return 0;
    return lineOfOffset(index.offset[path.back()]);
}

bool JsonSource::has(const std::string& pointer) const {
    bool complete = false;
    valuesAlong(*this, pointer, complete);
    return complete;
}

void JsonSource::fail(const std::vector<std::string>& anchors, const std::string& field,
                      const std::string& message) const {
    const bool isPointer = !field.empty() && field.front() == '/';
    const int line = isPointer && !index.empty() ? lineAt(field) : lineOf(anchors);
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

InputError tooLargeError(const std::string& file, std::size_t bytes, std::size_t maxBytes) {
    const auto mib = [](std::size_t n) {
        return n % limits::kMebibyte == 0 ? std::to_string(n / limits::kMebibyte) : formatFixed(static_cast<double>(n) / limits::kMebibyte, 1);
    };
    return InputError(file, 0, "", "the file is " + (bytes > maxBytes + limits::kMebibyte ? mib(bytes) + " MiB" : std::to_string(bytes) + " bytes") +
                                       ", over the limit of " + mib(maxBytes) + " MiB for this kind of input (docs/errors.md, Limits)");
}

std::size_t findControlCharacter(std::string_view text) {
    for (std::size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        if ((c < 0x20 && c != '\t' && c != '\n') || c == 0x7F) return i;
    }
    return std::string_view::npos;
}

std::string describeControlCharacter(char c) {
    static const char* const kNames[32] = {"NUL", "SOH", "STX", "ETX", "EOT", "ENQ", "ACK", "BEL", "BS", "TAB", "LF",
                                           "VT",  "FF",  "CR",  "SO",  "SI",  "DLE", "DC1", "DC2", "DC3", "DC4", "NAK",
                                           "SYN", "ETB", "CAN", "EM",  "SUB", "ESC", "FS",  "GS",  "RS",  "US"};
    const auto code = static_cast<unsigned char>(c);
    char hex[8];
    std::snprintf(hex, sizeof hex, "U+%04X", code);
    return std::string(hex) + " (" + (code < 32 ? kNames[code] : code == 0x7F ? "DEL" : "?") + ")";
}

std::string readTextFile(const std::filesystem::path& path, std::size_t maxBytes) {
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
    // Refused before a byte is read; the loop below also stops a file that grows meanwhile.
    if (static_cast<std::uintmax_t>(opened.st_size) > maxBytes) {
        ::close(descriptor);
        throw tooLargeError(name, static_cast<std::size_t>(opened.st_size), maxBytes);
    }
    text.reserve(static_cast<std::size_t>(opened.st_size));
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
        if (text.size() > maxBytes) {
            ::close(descriptor);
            throw tooLargeError(name, text.size(), maxBytes);
        }
    }
    ::close(descriptor);
    return text;
}

JsonSource parseJsonText(std::string text, std::string fileName, std::size_t maxBytes) {
    // Offsets are 32-bit: no limit may pass 4 GiB.
    static_assert(limits::kJsonFileBytes < (std::size_t{1} << 32));
    maxBytes = std::min(maxBytes, limits::kJsonFileBytes);
    if (text.size() > maxBytes) throw tooLargeError(fileName, text.size(), maxBytes);
    JsonSource source{std::move(fileName), std::string(withoutByteOrderMark(text)), {}, {}};
    std::vector<std::uint32_t>& blockLines = source.index.blockLines;
    blockLines.reserve(source.text.size() / kLineBlock + 1);
    std::uint32_t newlines = 0;
    for (std::size_t block = 0; block < source.text.size(); block += kLineBlock) {
        blockLines.push_back(newlines);
        const auto first = source.text.begin() + static_cast<std::ptrdiff_t>(block);
        newlines += static_cast<std::uint32_t>(std::count(first, first + static_cast<std::ptrdiff_t>(std::min(kLineBlock, source.text.size() - block)), '\n'));
    }
    std::size_t run = 0;
    for (std::size_t i = 0; i < source.text.size(); ++i) {
        const char c = source.text[i];
        run = c == ' ' || c == '\t' || c == '\r' || c == '\n' ? run + 1 : 0;
        if (run > limits::kJsonWhitespaceRun)
            throw InputError(source.file, source.lineOfOffset(i + 1 - run), "",
                             "more than " + std::to_string(limits::kJsonWhitespaceRun) +
                                 " bytes of white space in a row, from this line on (docs/errors.md, Limits)");
    }
    const char* furthest = source.text.data();
    IndexingBuilder builder(source, &furthest);
    const TrackingIterator first(source.text.data(), &furthest);
    const TrackingIterator last(source.text.data() + source.text.size(), nullptr);
    try {
        json::sax_parse(first, last, &builder);
    } catch (const nlohmann::json::exception& e) {
        // Not raised through parse_error (should not happen); still the user's file.
        throw InputError(source.file, 0, "", "not valid JSON: " + shortened(withoutExceptionPrefix(e.what())));
    }
    return source;
}

JsonSource readJsonFile(const std::filesystem::path& path, std::size_t maxBytes) {
    return parseJsonText(readTextFile(path, maxBytes), path.string(), maxBytes);
}

}  // namespace signstim::stimuli
