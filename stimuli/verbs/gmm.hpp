#pragma once
// Gaussian mixture model of 3-D hand locations (SPEC §3.5), fitted by EM; the number of
// components is chosen by BIC. Deterministic: initial means come from equal-count slices of
// the data along its principal axis, so no random numbers are drawn at all.
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace signstim::stimuli {

struct GaussianComponent {
    double weight = 1.0;
    glm::dvec3 meanMm{0.0};
    glm::dmat3 covarianceMm2{1.0};  // symmetric positive definite
};

struct GaussianMixture {
    std::vector<GaussianComponent> components;

    double logDensity(const glm::dvec3& point) const;  // log p(point)
    // Σ log p(point) over the points (factorises the covariances once).
    double sumLogDensity(const std::vector<glm::dvec3>& points) const;
};

struct MixtureFitOptions {
    int maxComponents = 4;
    int maxIterations = 300;
    double tolerance = 1e-9;  // relative change of the mean log-likelihood that stops EM
    // Added to every covariance diagonal (mm²): keeps components from collapsing onto a few
    // points; 1 mm is below any motion-capture noise.
    double varianceFloorMm2 = 1.0;
};

struct MixtureFit {
    GaussianMixture mixture;
    double logLikelihood = 0.0;
    double bic = 0.0;
};

// EM for a fixed number of components. Throws std::invalid_argument when there are fewer
// points than components.
MixtureFit fitGaussianMixture(const std::vector<glm::dvec3>& points, int componentCount,
                              const MixtureFitOptions& options = {});

// Fits 1..maxComponents components (as many as the data supports) and keeps the lowest
// BIC = −2 ln L + p ln n, p = (K − 1) + 3K + 6K.
MixtureFit fitGaussianMixtureByBic(const std::vector<glm::dvec3>& points,
                                   const MixtureFitOptions& options = {});

}  // namespace signstim::stimuli
