#include "stimuli/verbs/polynomial.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>

namespace signstim::stimuli {

std::string toString(Inflection inflection) {
    return inflection == Inflection::ObjectOnly ? "object" : "subject-object";
}

std::size_t PolynomialBasis::termCount() const {
    if (degree < 0 || degree > 3) throw std::invalid_argument("polynomial degree must be 0..3");
    if (inflection == Inflection::ObjectOnly) return static_cast<std::size_t>(degree) + 1;
    return static_cast<std::size_t>((degree + 1) * (degree + 2) / 2);
}

std::vector<double> PolynomialBasis::terms(double s, double o) const {
    std::vector<double> result;
    result.reserve(termCount());
    if (inflection == Inflection::ObjectOnly) {
        double power = 1.0;
        for (int k = 0; k <= degree; ++k, power *= o) result.push_back(power);
        return result;
    }
    // Total degree k: s^k, s^(k-1) o, ..., o^k — the SPEC §3.4 order.
    for (int k = 0; k <= degree; ++k) {
        for (int j = 0; j <= k; ++j) {
            double term = 1.0;
            for (int a = 0; a < k - j; ++a) term *= s;
            for (int b = 0; b < j; ++b) term *= o;
            result.push_back(term);
        }
    }
    return result;
}

double Polynomial::operator()(double subject, double object) const {
    const std::vector<double> t = basis.terms(subject, object);
    if (t.size() != coefficients.size()) throw std::invalid_argument("polynomial coefficient count");
    double sum = 0.0;
    for (std::size_t i = 0; i < t.size(); ++i) sum += coefficients[i] * t[i];
    return sum;
}

Polynomial fitPolynomial(const PolynomialBasis& basis, const std::vector<Sample2>& inputs,
                         const std::vector<double>& values, double ridge) {
    if (inputs.empty() || inputs.size() != values.size()) {
        throw std::invalid_argument("fitPolynomial: inputs and values must be non-empty and match");
    }
    const Eigen::Index terms = static_cast<Eigen::Index>(basis.termCount());
    const Eigen::Index rows = static_cast<Eigen::Index>(inputs.size());
    const Eigen::Index ridgeRows = ridge > 0.0 ? terms - 1 : 0;
    Eigen::MatrixXd design = Eigen::MatrixXd::Zero(rows + ridgeRows, terms);
    Eigen::VectorXd target = Eigen::VectorXd::Zero(rows + ridgeRows);
    for (Eigen::Index i = 0; i < rows; ++i) {
        const std::vector<double> t = basis.terms(inputs[i].subject, inputs[i].object);
        for (Eigen::Index j = 0; j < terms; ++j) design(i, j) = t[static_cast<std::size_t>(j)];
        target(i) = values[static_cast<std::size_t>(i)];
    }
    for (Eigen::Index j = 1; j <= ridgeRows; ++j) design(rows + j - 1, j) = std::sqrt(ridge);
    const Eigen::VectorXd solution = design.completeOrthogonalDecomposition().solve(target);
    Polynomial result{basis, {}};
    result.coefficients.assign(solution.data(), solution.data() + solution.size());
    return result;
}

}  // namespace signstim::stimuli
