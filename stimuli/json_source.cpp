#include "stimuli/json_source.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace signstim::stimuli {

int JsonSource::lineOf(const std::vector<std::string>& anchors) const {
    std::size_t position = 0;
    std::size_t found = std::string::npos;
    for (const std::string& anchor : anchors) {
        const std::size_t at = text.find(anchor, position);
        if (at == std::string::npos) break;
        found = at;
        position = at + anchor.size();
    }
    if (found == std::string::npos) return 0;
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(found), '\n'));
}

void JsonSource::fail(const std::vector<std::string>& anchors, const std::string& field,
                      const std::string& message) const {
    throw InputError(file, lineOf(anchors), field, message);
}

std::string readTextFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path.string(), 0, "", "cannot open the file (does it exist and is it readable?)");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

JsonSource parseJsonText(std::string text, std::string fileName) {
    JsonSource source{std::move(fileName), std::move(text), {}};
    try {
        source.root = nlohmann::json::parse(source.text);
    } catch (const nlohmann::json::parse_error& e) {
        const std::size_t byte = std::min<std::size_t>(e.byte, source.text.size());
        const int line = 1 + static_cast<int>(std::count(source.text.begin(),
                                                         source.text.begin() + static_cast<std::ptrdiff_t>(byte), '\n'));
        throw InputError(source.file, line, "", std::string("not valid JSON: ") + e.what());
    }
    return source;
}

JsonSource readJsonFile(const std::filesystem::path& path) { return parseJsonText(readTextFile(path), path.string()); }

}  // namespace signstim::stimuli
