#include "stimuli/verbs/signing_space.hpp"

#include "common/error.hpp"
#include "common/number_format.hpp"

#include <cmath>
#include <numbers>

namespace signstim::stimuli {

void checkArcPosition(double position, const std::string& source, const std::string& field) {
    if (!(position >= -1.0 && position <= 1.0)) {
        throw InputError(source, 0, field,
                         "arc position " + formatNumber(position) +
                             " is outside [-1, 1] (-1 = signer's far left, 0 = straight ahead, "
                             "1 = far right)");
    }
}

double arcAngleRadians(double position) { return 0.5 * std::numbers::pi * position; }

glm::dvec3 arcPoint(double position, const SigningSpace& space) {
    checkArcPosition(position, "<arc position>", "p");
    const double psi = arcAngleRadians(position);
    return space.chestMm + space.arcRadiusMm * glm::dvec3(std::sin(psi), 0.0, std::cos(psi));
}

}  // namespace signstim::stimuli
