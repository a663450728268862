#pragma once
// The paper's figures from an analysis (docs/analysis.md, "Figures"), as drawings
// (renderer/drawing.hpp) that become SVG (analysis/svg.hpp) and PNG (analysis/figure_png.hpp):
//  - fig6-comprehension: phase-1 accuracy per version, box plots of the participants' scores
//    (Figure 6 of the paper);
//  - fig7-likert: phase-2 ratings per version, box plots (Figure 7);
//  - fig8-likert-by-verb: mean rating per verb and version with 95 % confidence intervals (Figure 8);
//  - fig8b-comprehension-by-verb: the same for phase-1 accuracy (the paper has no such figure).
// Box plots: box from the first to the third quartile, a bar at the median, whiskers to the
// furthest score within 1.5 box lengths, scores beyond as small circles, the mean as a dot.
// Significant pairs (Holm-adjusted Mann–Whitney p and Kruskal–Wallis p below alpha) are
// joined by a bracket with stars: * below alpha, ** below alpha/5, *** below alpha/50
// (.05, .01, .001 at the default alpha).
#include "analysis/study_analysis.hpp"
#include "renderer/drawing.hpp"

#include <string>
#include <vector>

namespace signstim::analysis {

// The scale at which the layout measures text: the renderer's label font at 2 pixels per unit,
// whose cells are wider than the vector fonts of the SVG (the viewer's sans-serif) and of the
// PNG (DejaVu Sans through FreeType, analysis/figure_png.hpp), so the text fits in both.
inline constexpr double kFigurePixelsPerUnit = 2.0;

struct Figure {
    std::string name;     // "fig6-comprehension" (files: figures/NAME.svg, figures/NAME.png)
    std::string title;    // "Figure 6 - Comprehension (phase 1)"
    std::string caption;  // one paragraph for the report
    render::Drawing drawing;
};

// Every figure the analysis has data for (a phase without data gives no figure).
std::vector<Figure> studyFigures(const StudyAnalysis& analysis);

// "*", "**", "***" or "" for an adjusted p at `alpha`.
std::string significanceStars(double p, double alpha);

// The colour of a version in every figure (Okabe–Ito palette: point blue, vector orange,
// animator green, uninflected purple; others grey).
render::Colour versionColour(const std::string& version);

}  // namespace signstim::analysis
