#include "stimuli/verbs/gmm.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <stdexcept>

namespace signstim::stimuli {
namespace {

Eigen::Vector3d toEigen(const glm::dvec3& v) { return {v.x, v.y, v.z}; }
glm::dvec3 toGlm(const Eigen::Vector3d& v) { return {v(0), v(1), v(2)}; }

Eigen::Matrix3d toEigen(const glm::dmat3& m) {
    Eigen::Matrix3d result;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) result(r, c) = m[c][r];
    return result;
}

glm::dmat3 toGlm(const Eigen::Matrix3d& m) {
    glm::dmat3 result;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) result[c][r] = m(r, c);
    return result;
}

double logSumExp(const std::vector<double>& values) {
    const double top = *std::max_element(values.begin(), values.end());
    if (!std::isfinite(top)) return top;
    double sum = 0.0;
    for (double v : values) sum += std::exp(v - top);
    return top + std::log(sum);
}

// Per component: log weight − ½ log det(2πΣ), and the Cholesky factor for Mahalanobis terms.
struct PreparedComponent {
    double logNormaliser = 0.0;
    Eigen::Vector3d mean;
    Eigen::LLT<Eigen::Matrix3d> cholesky;
};

std::vector<PreparedComponent> prepare(const GaussianMixture& mixture) {
    std::vector<PreparedComponent> prepared;
    for (const GaussianComponent& c : mixture.components) {
        PreparedComponent p;
        p.mean = toEigen(c.meanMm);
        p.cholesky.compute(toEigen(c.covarianceMm2));
        if (p.cholesky.info() != Eigen::Success) throw std::invalid_argument("covariance not positive definite");
        const Eigen::Matrix3d l = p.cholesky.matrixL();
        const double logDet = 2.0 * (std::log(l(0, 0)) + std::log(l(1, 1)) + std::log(l(2, 2)));
        p.logNormaliser = std::log(c.weight) - 0.5 * (3.0 * std::log(2.0 * std::numbers::pi) + logDet);
        prepared.push_back(std::move(p));
    }
    return prepared;
}

double componentLogDensity(const PreparedComponent& p, const Eigen::Vector3d& x) {
    const Eigen::Vector3d solved = p.cholesky.matrixL().solve(x - p.mean);
    return p.logNormaliser - 0.5 * solved.squaredNorm();
}

}  // namespace

double GaussianMixture::logDensity(const glm::dvec3& point) const {
    const std::vector<PreparedComponent> prepared = prepare(*this);
    std::vector<double> terms;
    terms.reserve(prepared.size());
    const Eigen::Vector3d x = toEigen(point);
    for (const PreparedComponent& p : prepared) terms.push_back(componentLogDensity(p, x));
    return logSumExp(terms);
}

double GaussianMixture::sumLogDensity(const std::vector<glm::dvec3>& points) const {
    const std::vector<PreparedComponent> prepared = prepare(*this);
    std::vector<double> terms(prepared.size());
    double sum = 0.0;
    for (const glm::dvec3& point : points) {
        const Eigen::Vector3d x = toEigen(point);
        for (std::size_t k = 0; k < prepared.size(); ++k) terms[k] = componentLogDensity(prepared[k], x);
        sum += logSumExp(terms);
    }
    return sum;
}

MixtureFit fitGaussianMixture(const std::vector<glm::dvec3>& points, int componentCount,
                              const MixtureFitOptions& options) {
    const int n = static_cast<int>(points.size());
    if (componentCount < 1 || n < componentCount) {
        throw std::invalid_argument("fitGaussianMixture: fewer points than components");
    }
    std::vector<Eigen::Vector3d> x;
    x.reserve(points.size());
    for (const glm::dvec3& p : points) x.push_back(toEigen(p));
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& v : x) mean += v;
    mean /= n;
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const auto& v : x) scatter += (v - mean) * (v - mean).transpose();
    scatter /= n;
    const Eigen::Matrix3d floor = options.varianceFloorMm2 * Eigen::Matrix3d::Identity();

    // Deterministic initialisation: order the points along the principal axis (ties by
    // index) and give each component one equal-count slice.
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
    const Eigen::Vector3d axis = solver.eigenvectors().col(2);
    std::vector<int> order(static_cast<std::size_t>(n));
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        return axis.dot(x[static_cast<std::size_t>(a)]) < axis.dot(x[static_cast<std::size_t>(b)]);
    });
    Eigen::MatrixXd responsibility = Eigen::MatrixXd::Zero(n, componentCount);
    for (int rank = 0; rank < n; ++rank) {
        const int k = std::min(componentCount - 1, rank * componentCount / n);
        responsibility(order[static_cast<std::size_t>(rank)], k) = 1.0;
    }

    GaussianMixture mixture;
    double previous = -std::numeric_limits<double>::infinity();
    double logLikelihood = previous;
    for (int iteration = 0; iteration < options.maxIterations; ++iteration) {
        // M step.
        mixture.components.assign(static_cast<std::size_t>(componentCount), {});
        for (int k = 0; k < componentCount; ++k) {
            const double total = responsibility.col(k).sum();
            GaussianComponent& c = mixture.components[static_cast<std::size_t>(k)];
            if (total < 1e-12) {  // an emptied component restarts as the whole-data Gaussian
                c.weight = 1e-12;
                c.meanMm = toGlm(mean);
                c.covarianceMm2 = toGlm(Eigen::Matrix3d(scatter + floor));
                continue;
            }
            Eigen::Vector3d m = Eigen::Vector3d::Zero();
            for (int i = 0; i < n; ++i) m += responsibility(i, k) * x[static_cast<std::size_t>(i)];
            m /= total;
            Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
            for (int i = 0; i < n; ++i) {
                const Eigen::Vector3d d = x[static_cast<std::size_t>(i)] - m;
                covariance += responsibility(i, k) * d * d.transpose();
            }
            covariance = covariance / total + floor;
            c.weight = total / n;
            c.meanMm = toGlm(m);
            c.covarianceMm2 = toGlm(Eigen::Matrix3d(0.5 * (covariance + covariance.transpose())));
        }
        // E step.
        const std::vector<PreparedComponent> prepared = prepare(mixture);
        logLikelihood = 0.0;
        std::vector<double> terms(static_cast<std::size_t>(componentCount));
        for (int i = 0; i < n; ++i) {
            for (int k = 0; k < componentCount; ++k) {
                terms[static_cast<std::size_t>(k)] =
                    componentLogDensity(prepared[static_cast<std::size_t>(k)], x[static_cast<std::size_t>(i)]);
            }
            const double total = logSumExp(terms);
            logLikelihood += total;
            for (int k = 0; k < componentCount; ++k) {
                responsibility(i, k) = std::exp(terms[static_cast<std::size_t>(k)] - total);
            }
        }
        if (std::abs(logLikelihood - previous) <= options.tolerance * std::abs(logLikelihood)) break;
        previous = logLikelihood;
    }
    const double parameters = (componentCount - 1) + 3.0 * componentCount + 6.0 * componentCount;
    return MixtureFit{mixture, logLikelihood, -2.0 * logLikelihood + parameters * std::log(static_cast<double>(n))};
}

MixtureFit fitGaussianMixtureByBic(const std::vector<glm::dvec3>& points, const MixtureFitOptions& options) {
    if (points.empty()) throw std::invalid_argument("fitGaussianMixtureByBic: no points");
    MixtureFit best = fitGaussianMixture(points, 1, options);
    for (int k = 2; k <= options.maxComponents; ++k) {
        // At least 10 points per full-covariance component (9 parameters each).
        if (static_cast<int>(points.size()) < 10 * k) break;
        MixtureFit fit = fitGaussianMixture(points, k, options);
        if (fit.bic < best.bic) best = std::move(fit);
    }
    return best;
}

}  // namespace signstim::stimuli
