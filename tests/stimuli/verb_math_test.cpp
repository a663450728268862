// Signing space, SORA conversions and polynomial least squares (SPEC §3.1, §3.4, §3.6).
#include "common/error.hpp"
#include "stimuli/verbs/gmm.hpp"
#include "stimuli/verbs/polynomial.hpp"
#include "stimuli/verbs/signing_space.hpp"
#include "stimuli/verbs/sora.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "common/random.hpp"

namespace signstim::stimuli {
namespace {

constexpr double kPi = std::numbers::pi;

// Issue 21: a verb's path between keys (sweptPathPoint). From the left to the right at chest
// height 50 mm in front of the chest centre the chord stays inside the torso (its front ~110
// mm ahead), 150 mm from the torso's axis; the swept path
// comes no nearer the axis than its keys and bows in front of the chest. A chord that moves
// straight out from the body, or passes far from it, is kept; the ends are the keys exactly.
TEST(SigningSpace, VerbPathSweepsAroundTheChestWhereItsChordWouldCutIn) {
    const auto fromAxis = [](const glm::dvec3& p) { return std::hypot(p.x, p.z - kVerbSweepAxisZMm); };
    const glm::dvec3 left(-300.0, 0.0, 50.0), right(300.0, 40.0, 50.0);
    EXPECT_EQ(sweptPathPoint(left, right, 0.0), left);
    EXPECT_EQ(sweptPathPoint(left, right, 1.0), right);
    double nearest = 1e9;
    for (int i = 1; i < 100; ++i) {
        const glm::dvec3 p = sweptPathPoint(left, right, i / 100.0);
        nearest = std::min(nearest, fromAxis(p));
        EXPECT_NEAR(p.y, 0.4 * i, 1e-9);  // the height changes evenly
    }
    EXPECT_GE(nearest, fromAxis(left) - 1e-6);
    const glm::dvec3 middle = sweptPathPoint(left, right, 0.5);
    EXPECT_NEAR(middle.x, 0.0, 1e-9);
    EXPECT_NEAR(middle.z, kVerbSweepAxisZMm + fromAxis(left), 1e-9);  // in front of the chest, at the keys' distance
    // The rate bounds the path's: at least the distance between neighbouring points per blend.
    const double rate = sweptPathRateMm(left, right);
    for (int i = 0; i < 100; ++i)
        EXPECT_LE(glm::distance(sweptPathPoint(left, right, i / 100.0), sweptPathPoint(left, right, (i + 1) / 100.0)),
                  rate / 100.0 + 1e-9);
    // Straight out from the chest: the chord.
    const glm::dvec3 chest(60.0, 0.0, 120.0), out(-150.0, 0.0, 460.0);
    EXPECT_EQ(sweptPathPoint(chest, out, 0.3), chest + 0.3 * (out - chest));
    EXPECT_DOUBLE_EQ(sweptPathRateMm(chest, out), glm::length(out - chest));
    // Across, but far out in front (beyond kVerbSweepFarMm): the chord.
    const glm::dvec3 farLeft(-200.0, 0.0, 400.0), farRight(200.0, 0.0, 400.0);
    EXPECT_EQ(sweptPathPoint(farLeft, farRight, 0.5), 0.5 * (farLeft + farRight));
}

TEST(SigningSpace, ArcPositionsMapToTheSemicircleAtChestHeight) {
    const SigningSpace space;
    const glm::dvec3 ahead = arcPoint(0.0, space);
    EXPECT_NEAR(ahead.x, 0.0, 1e-9);
    EXPECT_NEAR(ahead.z, 500.0, 1e-9);
    const glm::dvec3 farRight = arcPoint(1.0, space);
    EXPECT_NEAR(farRight.x, 500.0, 1e-9);
    EXPECT_NEAR(farRight.z, 0.0, 1e-9);
    // SPEC §3.1: 0.9 is the signer's far right, −0.6 is on the left.
    EXPECT_GT(arcPoint(0.9, space).x, 400.0);
    EXPECT_LT(arcPoint(-0.6, space).x, -300.0);
    for (double p = -1.0; p <= 1.0; p += 0.25) {
        EXPECT_NEAR(glm::length(arcPoint(p, space) - space.chestMm), 500.0, 1e-9);
        EXPECT_EQ(arcPoint(p, space).y, 0.0);
    }
}

TEST(SigningSpace, PositionsOutsideTheArcAreAnErrorNotAClamp) {
    EXPECT_THROW(arcPoint(1.01), InputError);
    EXPECT_THROW(arcPoint(-1.5), InputError);
    EXPECT_THROW(arcPoint(std::nan("")), InputError);
    EXPECT_NO_THROW(arcPoint(-1.0));
}

glm::dvec3 randomUnit(SplitMix64& rng) {
    for (;;) {
        const glm::dvec3 v(rng.normal(), rng.normal(), rng.normal());
        if (glm::length(v) > 1e-3) return glm::normalize(v);
    }
}

double matrixDistance(const glm::dmat3& a, const glm::dmat3& b) {
    double d = 0.0;
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r) d = std::max(d, std::abs(a[c][r] - b[c][r]));
    return d;
}

TEST(Sora, RoundTripsThroughQuaternionMatrixAndAxisAngleIncludingNearPi) {
    SplitMix64 rng(7);
    std::vector<double> angles{0.0, 1e-9, 1e-4, 0.3, 1.0, 2.0, 3.0, kPi - 1e-3, kPi - 1e-6, kPi - 1e-9};
    for (int i = 0; i < 40; ++i) angles.push_back(rng.uniform() * kPi);
    for (double angle : angles) {
        const glm::dvec3 axis = randomUnit(rng);
        const Sora phi = angle * axis;
        const glm::dquat q = soraToQuaternion(phi);
        EXPECT_NEAR(glm::length(q), 1.0, 1e-12);
        const Sora back = quaternionToSora(q);
        EXPECT_NEAR(glm::length(back - phi), 0.0, 1e-8) << "angle " << angle;
        const glm::dmat3 m = soraToMatrix(phi);
        EXPECT_NEAR(matrixDistance(m, glm::mat3_cast(q)), 0.0, 1e-12);
        // Near π the matrix route is ill-conditioned in the axis sign; the rotation is exact.
        EXPECT_NEAR(matrixDistance(soraToMatrix(matrixToSora(m)), m), 0.0, 1e-9) << "angle " << angle;
        EXPECT_LT(rotationAngleBetween(matrixToQuaternion(m), q), 1e-7) << "angle " << angle;
        const AxisAngle aa = soraToAxisAngle(phi);
        EXPECT_NEAR(aa.angleRadians, angle, 1e-12);
        EXPECT_NEAR(glm::length(axisAngleToSora(aa) - phi), 0.0, 1e-12);
    }
}

TEST(Sora, ExactlyPiAndBeyondMapBackIntoTheBall) {
    const Sora phi(0.0, 0.0, kPi);
    const Sora back = quaternionToSora(soraToQuaternion(phi));
    EXPECT_NEAR(glm::length(back), kPi, 1e-12);
    EXPECT_NEAR(std::abs(back.z), kPi, 1e-12);
    // 1.5π about z is −0.5π about z.
    const Sora wrapped = quaternionToSora(soraToQuaternion(Sora(0.0, 0.0, 1.5 * kPi)));
    EXPECT_NEAR(wrapped.z, -0.5 * kPi, 1e-12);
    // q and −q are the same rotation.
    const glm::dquat q = soraToQuaternion(Sora(0.4, -0.2, 0.9));
    EXPECT_NEAR(glm::length(quaternionToSora(-q) - quaternionToSora(q)), 0.0, 1e-12);
}

TEST(Sora, RollPitchYawComposeAsRzRyRx) {
    SplitMix64 rng(11);
    for (int i = 0; i < 50; ++i) {
        const double roll = (rng.uniform() * 2 - 1) * 179.0;
        const double pitch = (rng.uniform() * 2 - 1) * 89.0;
        const double yaw = (rng.uniform() * 2 - 1) * 179.0;
        const glm::dquat q = rollPitchYawDegreesToQuaternion(roll, pitch, yaw);
        const glm::dvec3 back = quaternionToRollPitchYawDegrees(q);
        EXPECT_NEAR(back.x, roll, 1e-8);
        EXPECT_NEAR(back.y, pitch, 1e-8);
        EXPECT_NEAR(back.z, yaw, 1e-8);
    }
    // Yaw alone turns +x toward +y (about z); pitch alone turns +z toward +x (about y).
    const glm::dquat yaw90 = rollPitchYawDegreesToQuaternion(0, 0, 90);
    EXPECT_NEAR(glm::length(yaw90 * glm::dvec3(1, 0, 0) - glm::dvec3(0, 1, 0)), 0.0, 1e-12);
    const glm::dquat pitch90 = rollPitchYawDegreesToQuaternion(0, 90, 0);
    EXPECT_NEAR(glm::length(pitch90 * glm::dvec3(0, 0, 1) - glm::dvec3(1, 0, 0)), 0.0, 1e-12);
    // The composition order: R = Rz·Ry·Rx applies roll first.
    const glm::dquat both = rollPitchYawDegreesToQuaternion(90, 0, 90);
    EXPECT_NEAR(glm::length(both * glm::dvec3(0, 1, 0) - glm::dvec3(0, 0, 1)), 0.0, 1e-12);
}

TEST(Sora, FingersAndPalmDirectionsBuildTheOrientation) {
    const glm::dquat q = orientationFromFingersPalm({0, 1, 0.2}, {0, 0, 1});
    EXPECT_NEAR(glm::length(fingersDirection(q) - glm::normalize(glm::dvec3(0, 1, 0.2))), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(palmDirection(q), fingersDirection(q)), 0.0, 1e-12);
    EXPECT_GT(palmDirection(q).z, 0.9);
    EXPECT_THROW(orientationFromFingersPalm({0, 1, 0}, {0, 2, 0}), std::invalid_argument);
}

TEST(Sora, SlerpTakesTheShortPathAndHitsTheEnds) {
    const glm::dquat a = soraToQuaternion({0, 0, 0.2});
    const glm::dquat b = -soraToQuaternion({0, 0, 1.0});  // same rotation, other hemisphere
    EXPECT_LT(rotationAngleBetween(slerpShortest(a, b, 0.0), a), 1e-12);
    EXPECT_LT(rotationAngleBetween(slerpShortest(a, b, 1.0), b), 1e-7);
    EXPECT_NEAR(rotationAngleBetween(slerpShortest(a, b, 0.5), soraToQuaternion({0, 0, 0.6})), 0.0, 1e-7);
}

TEST(Sora, MeanRotationOfASymmetricSpreadIsTheCentre) {
    const glm::dquat centre = soraToQuaternion({0.3, 2.9, -0.4});
    std::vector<glm::dquat> rotations;
    for (const glm::dvec3& d : {glm::dvec3(0.1, 0, 0), glm::dvec3(-0.1, 0, 0), glm::dvec3(0, 0.1, 0), glm::dvec3(0, -0.1, 0)})
        rotations.push_back(-(centre * soraToQuaternion(d)));  // sign must not matter
    EXPECT_LT(rotationAngleBetween(meanRotation(rotations), centre), 1e-9);
}

TEST(Polynomial, TermsFollowTheSpecOrder) {
    const PolynomialBasis cubic{Inflection::SubjectObject, 3};
    const std::vector<double> t = cubic.terms(2.0, 3.0);
    const std::vector<double> expected{1, 2, 3, 4, 6, 9, 8, 12, 18, 27};
    EXPECT_EQ(t, expected);
    const PolynomialBasis objectCubic{Inflection::ObjectOnly, 3};
    EXPECT_EQ(objectCubic.terms(5.0, 2.0), (std::vector<double>{1, 2, 4, 8}));
    EXPECT_EQ((PolynomialBasis{Inflection::SubjectObject, 1}.termCount()), 3u);
}

TEST(Polynomial, AKnownCubicIsRecoveredExactly) {
    const std::vector<double> truth{12.5, -3.0, 4.25, 1.5, -2.0, 0.75, 6.0, -1.25, 3.5, -0.5};
    const Polynomial known{{Inflection::SubjectObject, 3}, truth};
    const std::vector<double> arc{-0.9, -0.6, -0.3, 0.0, 0.3, 0.6, 0.9};
    std::vector<Sample2> inputs;
    std::vector<double> values;
    for (double s : arc)
        for (double o : arc)
            if (s != o) {
                inputs.push_back({s, o});
                values.push_back(known(s, o));
            }
    ASSERT_EQ(inputs.size(), 42u);
    const Polynomial fitted = fitPolynomial(known.basis, inputs, values);
    for (std::size_t i = 0; i < truth.size(); ++i) EXPECT_NEAR(fitted.coefficients[i], truth[i], 1e-9) << "term " << i;

    const Polynomial objectKnown{{Inflection::ObjectOnly, 3}, {1.0, -2.0, 0.5, 3.0}};
    std::vector<double> objectValues;
    for (const Sample2& x : inputs) objectValues.push_back(objectKnown(x.subject, x.object));
    const Polynomial objectFit = fitPolynomial(objectKnown.basis, inputs, objectValues);
    for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(objectFit.coefficients[i], objectKnown.coefficients[i], 1e-9);
}

TEST(Polynomial, LowerDegreeCannotFitACubicButIsTheBestLinearFit) {
    std::vector<Sample2> inputs;
    std::vector<double> values;
    for (int i = -5; i <= 5; ++i) {
        inputs.push_back({0.0, i / 5.0});
        values.push_back(std::pow(i / 5.0, 3));
    }
    const Polynomial linear = fitPolynomial({Inflection::ObjectOnly, 1}, inputs, values);
    EXPECT_NEAR(linear.coefficients[0], 0.0, 1e-12);
    EXPECT_GT(linear.coefficients[1], 0.5);  // slope of the best line through o³
    EXPECT_GT(std::abs(linear(0.0, 1.0) - 1.0), 0.1);
}

TEST(GaussianMixture, BicFindsTwoWellSeparatedClustersAndEmIsDeterministic) {
    SplitMix64 rng(3);
    std::vector<glm::dvec3> points;
    for (int i = 0; i < 150; ++i) points.push_back(glm::dvec3(-100, 0, 300) + 8.0 * glm::dvec3(rng.normal(), rng.normal(), rng.normal()));
    for (int i = 0; i < 100; ++i) points.push_back(glm::dvec3(150, 50, 250) + 5.0 * glm::dvec3(rng.normal(), rng.normal(), rng.normal()));
    const MixtureFit fit = fitGaussianMixtureByBic(points);
    ASSERT_EQ(fit.mixture.components.size(), 2u);
    const MixtureFit again = fitGaussianMixtureByBic(points);
    EXPECT_EQ(fit.logLikelihood, again.logLikelihood);
    double weightNear150 = 0.0;
    for (const GaussianComponent& c : fit.mixture.components)
        if (glm::length(c.meanMm - glm::dvec3(150, 50, 250)) < 3.0) weightNear150 = c.weight;
    EXPECT_NEAR(weightNear150, 0.4, 1e-6);
    EXPECT_GT(fit.mixture.logDensity({150, 50, 250}), fit.mixture.logDensity({20, 20, 280}) + 10.0);
}

}  // namespace
}  // namespace signstim::stimuli
