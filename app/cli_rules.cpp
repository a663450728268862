#include "app/cli_rules.hpp"

#include <charconv>
#include <cmath>
#include <string>

namespace signstim::app {
namespace {

// "" when `text` is a whole decimal integer (a sign only when `signedAllowed`), else why not.
std::string integerProblem(const std::string& text, bool signedAllowed) {
    std::size_t start = signedAllowed && !text.empty() && text[0] == '-' ? 1 : 0;
    bool digits = text.size() > start;
    for (std::size_t i = start; i < text.size(); ++i) digits = digits && text[i] >= '0' && text[i] <= '9';
    if (digits) return "";
    return std::string("expected ") + (signedAllowed ? "an integer" : "a whole number >= 0") + ", got '" + text + "'";
}

// "" when `text` is a whole finite decimal number ("0.5", "-3", "1e-2"), else why not.
std::string numberProblem(const std::string& text) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (!text.empty() && error == std::errc() && end == text.data() + text.size() && std::isfinite(value)) return "";
    return "expected a number, got '" + text + "'";
}

}  // namespace

void requirePlainNumbers(CLI::App& app) {
    for (CLI::Option* option : app.get_options()) {
        const std::string type = option->get_type_name();
        if (type == "INT" || type == "UINT")
            option->check(CLI::Validator(
                [signedAllowed = type == "INT"](std::string& text) { return integerProblem(text, signedAllowed); },
                ""));
        else if (type == "FLOAT")
            option->check(CLI::Validator([](std::string& text) { return numberProblem(text); }, ""));
    }
    for (CLI::App* subcommand : app.get_subcommands([](CLI::App*) { return true; })) requirePlainNumbers(*subcommand);
}

}  // namespace signstim::app
