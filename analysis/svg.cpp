#include "analysis/svg.hpp"

#include "stimuli/study/study_exports.hpp"

#include <cmath>
#include <cstdio>

namespace signstim::analysis {

namespace {

using namespace render;

// At most 2 decimals, no trailing zeros, no "-0": locale-independent.
std::string num(double value) {
    const long hundredths = std::lround(value * 100.0);
    const long whole = std::labs(hundredths) / 100, fraction = std::labs(hundredths) % 100;
    std::string text = (hundredths < 0 ? "-" : "") + std::to_string(whole);
    if (fraction != 0) {
        char digits[4];
        std::snprintf(digits, sizeof digits, "%02ld", fraction);
        text += '.';
        text += digits[0];
        if (digits[1] != '0') text += digits[1];
    }
    return text;
}

std::string colour(const Colour& c) {
    char text[8];
    std::snprintf(text, sizeof text, "#%02x%02x%02x", c.r, c.g, c.b);
    return text;
}

std::string item(const DrawRect& r) {
    std::string s = "<rect x=\"" + num(r.x) + "\" y=\"" + num(r.y) + "\" width=\"" + num(r.width) + "\" height=\"" + num(r.height) +
                    "\" fill=\"" + (r.fill ? colour(*r.fill) : "none") + "\"";
    if (r.stroke) s += " stroke=\"" + colour(*r.stroke) + "\" stroke-width=\"" + num(r.strokeWidth) + "\"";
    return s + "/>";
}

std::string item(const DrawLine& l) {
    return "<line x1=\"" + num(l.x1) + "\" y1=\"" + num(l.y1) + "\" x2=\"" + num(l.x2) + "\" y2=\"" + num(l.y2) + "\" stroke=\"" +
           colour(l.colour) + "\" stroke-width=\"" + num(l.width) + "\"/>";
}

std::string item(const DrawDisc& d) {
    std::string s = "<circle cx=\"" + num(d.cx) + "\" cy=\"" + num(d.cy) + "\" r=\"" + num(d.radius) + "\" fill=\"" + colour(d.fill) + "\"";
    if (d.stroke) s += " stroke=\"" + colour(*d.stroke) + "\" stroke-width=\"" + num(d.strokeWidth) + "\"";
    return s + " shape-rendering=\"geometricPrecision\"/>";
}

std::string item(const DrawText& t) {
    std::string s = "<text x=\"" + num(t.x) + "\" y=\"" + num(t.y) + "\" font-size=\"" + num(t.size) + "\"";
    if (t.anchor == TextAnchor::Middle) s += " text-anchor=\"middle\"";
    if (t.anchor == TextAnchor::End) s += " text-anchor=\"end\"";
    if (t.bold) s += " font-weight=\"bold\"";
    if (!(t.colour == Colour{})) s += " fill=\"" + colour(t.colour) + "\"";
    if (t.vertical) s += " transform=\"rotate(-90 " + num(t.x) + " " + num(t.y) + ")\"";
    return s + ">" + stimuli::escapeHtml(t.text) + "</text>";
}

}  // namespace

std::string svgElement(const Drawing& drawing) {
    std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(drawing.width) + "\" height=\"" + num(drawing.height) +
                    "\" viewBox=\"0 0 " + num(drawing.width) + " " + num(drawing.height) +
                    "\" role=\"img\" font-family=\"DejaVu Sans, Verdana, Arial, sans-serif\" shape-rendering=\"crispEdges\">\n";
    s += "<title>" + stimuli::escapeHtml(drawing.title) + "</title>\n";
    s += "<rect width=\"100%\" height=\"100%\" fill=\"" + colour(drawing.background) + "\"/>\n";
    for (const DrawItem& i : drawing.items) s += std::visit([](const auto& shape) { return item(shape); }, i) + "\n";
    return s + "</svg>\n";
}

std::string svgDocument(const Drawing& drawing) {
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + svgElement(drawing);
}

}  // namespace signstim::analysis
