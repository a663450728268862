#include "common/error.hpp"

#include <cstring>

namespace signstim {
namespace {
std::string compose(const std::string& file, int line, int column, const std::string& field,
                    const std::string& message) {
    std::string text;
    if (!file.empty()) {
        text += file;
        if (line > 0) text += ":" + std::to_string(line);
        if (line > 0 && column > 0) text += ":" + std::to_string(column);
        text += ": ";
    }
    if (!field.empty()) text += "field '" + field + "': ";
    text += message;
    return text;
}
}  // namespace

InputError::InputError(std::string file, int line, std::string field, const std::string& message)
    : InputError(std::move(file), line, 0, std::move(field), message) {}

InputError::InputError(std::string file, int line, int column, std::string field, const std::string& message)
    : std::runtime_error(compose(file, line, column, field, message)),
      file_(std::move(file)),
      line_(line),
      column_(column),
      field_(std::move(field)),
      detail_(message) {}

InputError::InputError(const std::string& message)
    : std::runtime_error(message), detail_(message) {}

IoError::IoError(std::string path, const std::string& action, int errorNumber)
    : IoError(std::move(path), action, errorNumber != 0 ? std::string(std::strerror(errorNumber)) : std::string()) {}

IoError::IoError(std::string path, const std::string& action, const std::string& reason)
    : EnvironmentError(path + ": " + action + (reason.empty() ? std::string() : ": " + reason)),
      path_(std::move(path)) {}

}  // namespace signstim
