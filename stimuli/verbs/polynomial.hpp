#pragma once
// Polynomials of the arc positions of a verb's subject s and object o (SPEC §3.4): the full
// bivariate polynomial of total degree d with terms ordered
//   [1, s, o, s², so, o², s³, s²o, so², o³]   (d = 3, 10 terms),
// or, for verbs that inflect for the object only, [1, o, o², o³] (4 terms). Lower degrees
// (0..2) are the evaluation baselines of SPEC §3.8.
#include <string>
#include <vector>

namespace signstim::stimuli {

enum class Inflection { SubjectObject, ObjectOnly };

std::string toString(Inflection inflection);  // "subject-object" | "object"

struct PolynomialBasis {
    Inflection inflection = Inflection::SubjectObject;
    int degree = 3;  // 0..3

    std::size_t termCount() const;
    // The term values at (s, o); object-only bases ignore s.
    std::vector<double> terms(double subject, double object) const;
};

struct Polynomial {
    PolynomialBasis basis;
    std::vector<double> coefficients;  // basis.termCount() values

    double operator()(double subject, double object) const;
};

struct Sample2 {
    double subject = 0.0;
    double object = 0.0;
};

// Least squares (Eigen complete orthogonal decomposition: the minimum-norm solution when the
// design is rank deficient, e.g. too few distinct positions in a held-out fold), with an
// optional ridge λ·|c|² on every coefficient but the constant. Throws std::invalid_argument
// when inputs and values differ in length or are empty.
Polynomial fitPolynomial(const PolynomialBasis& basis, const std::vector<Sample2>& inputs,
                         const std::vector<double>& values, double ridge = 0.0);

}  // namespace signstim::stimuli
