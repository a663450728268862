#pragma once
// A drawing (renderer/drawing.hpp) as a standalone SVG 1.1 document, or as an <svg> element to
// put inside an HTML page. Numbers are written with at most 2 decimals, text is escaped, and
// the same drawing gives the same bytes.
#include "renderer/drawing.hpp"

#include <string>

namespace signstim::analysis {

// With the XML declaration: a file of its own (figures/*.svg).
std::string svgDocument(const render::Drawing& drawing);
// The <svg> element alone (inline in report.html), with role="img" and its title.
std::string svgElement(const render::Drawing& drawing);

// Text in SVG and HTML is escaped by the project's one function, stimuli::escapeHtml
// (stimuli/study/study_exports.hpp: & < > " ' as entities, safe in XML too).

}  // namespace signstim::analysis
