#include "stimuli/verbs/verb_models.hpp"

#include "common/number_format.hpp"
#include "stimuli/verbs/sora.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <set>

namespace signstim::stimuli {
namespace {

using Json = nlohmann::ordered_json;

std::vector<Sample2> inputsOf(const std::vector<const CorpusExample*>& examples) {
    std::vector<Sample2> inputs;
    for (const CorpusExample* e : examples) inputs.push_back({e->subject, e->object});
    return inputs;
}

Vector3Polynomial fitVector3(const PolynomialBasis& basis, const std::vector<Sample2>& inputs,
                             const std::vector<glm::dvec3>& values, double ridge) {
    std::vector<double> xs, ys, zs;
    for (const glm::dvec3& v : values) {
        xs.push_back(v.x);
        ys.push_back(v.y);
        zs.push_back(v.z);
    }
    return {fitPolynomial(basis, inputs, xs, ridge), fitPolynomial(basis, inputs, ys, ridge),
            fitPolynomial(basis, inputs, zs, ridge)};
}

// 10 significant digits: far below any measurement, and stable against last-bit differences.
// A value that is not finite is kept (written as null), so that formatCheckedVerbModels refuses
// it rather than a 0 standing in for it unseen.
double rounded(double value) {
    if (!std::isfinite(value)) return value;
    if (value == 0.0) return 0.0;
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.10g", value);
    const double result = std::strtod(buffer, nullptr);
    return result == 0.0 ? 0.0 : result;
}

Json numbers(const std::vector<double>& values) {
    Json array = Json::array();
    for (double v : values) array.push_back(rounded(v));
    return array;
}

Json vec3Json(const glm::dvec3& v) { return numbers({v.x, v.y, v.z}); }
Json quatJson(const glm::dquat& q) { return numbers({q.w, q.x, q.y, q.z}); }
Json polyJson(const Vector3Polynomial& p) {
    Json o = Json::object();
    o["x"] = numbers(p.x.coefficients);
    o["y"] = numbers(p.y.coefficients);
    o["z"] = numbers(p.z.coefficients);
    return o;
}

}  // namespace

glm::dvec3 Vector3Polynomial::operator()(double subject, double object) const {
    return {x(subject, object), y(subject, object), z(subject, object)};
}

glm::dquat OrientationModel::predict(std::size_t hand, std::size_t keyframe, double subject, double object) const {
    const Sora phi = relativeSora[hand][keyframe](subject, object);
    return glm::normalize(mean[hand][keyframe] * soraToQuaternion(phi));
}

const VerbModel* TrainedVerbModels::find(const std::string& verb) const {
    for (const VerbModel& model : verbs)
        if (model.verb == verb) return &model;
    return nullptr;
}

std::vector<glm::dvec3> pathSamples(const std::vector<glm::dvec3>& positions) {
    std::vector<glm::dvec3> samples;
    if (positions.empty()) return samples;
    samples.push_back(positions.front());
    for (std::size_t k = 1; k < positions.size(); ++k)
        for (int j = 1; j <= 10; ++j) samples.push_back(positions[k - 1] + (j / 10.0) * (positions[k] - positions[k - 1]));
    return samples;
}

VerbModel trainVerbModel(const VerbDefinition& verb, const std::vector<const CorpusExample*>& examples,
                         const ModelOptions& options) {
    VerbModel model;
    model.verb = verb.name;
    model.basis = PolynomialBasis{verb.inflection, options.degree};
    model.hands = verb.handCount();
    model.keyframes = verb.keyframeCount();
    model.trainingExamples = examples.size();
    if (examples.size() < model.basis.termCount())
        throw InputError("<corpus>", 0, "verb",
                         verb.name + " has " + std::to_string(examples.size()) + " examples; the degree-" +
                             std::to_string(options.degree) + " model needs at least " +
                             std::to_string(model.basis.termCount()));
    const std::vector<Sample2> inputs = inputsOf(examples);
    const auto poseOf = [&](std::size_t i, std::size_t h, std::size_t k) -> const HandPose& {
        return examples[i]->poses[h][k];
    };
    model.point.position.resize(model.hands);
    model.orientation.mean.resize(model.hands);
    model.orientation.relativeSora.resize(model.hands);
    for (std::size_t h = 0; h < model.hands; ++h) {
        for (std::size_t k = 0; k < model.keyframes; ++k) {
            std::vector<glm::dvec3> positions;
            std::vector<glm::dquat> rotations;
            for (std::size_t i = 0; i < examples.size(); ++i) {
                positions.push_back(poseOf(i, h, k).positionMm);
                rotations.push_back(poseOf(i, h, k).orientation);
            }
            model.point.position[h].push_back(fitVector3(model.basis, inputs, positions, options.ridge));
            // SPEC §3.6 [D]: fit Φ relative to the mean rotation, away from the |Φ| = π wrap.
            const glm::dquat mean = meanRotation(rotations);
            std::vector<glm::dvec3> relative;
            for (const glm::dquat& q : rotations) relative.push_back(quaternionToSora(glm::inverse(mean) * q));
            model.orientation.mean[h].push_back(mean);
            model.orientation.relativeSora[h].push_back(fitVector3(model.basis, inputs, relative, options.ridge));
        }
    }
    // VectorModel.
    for (std::size_t k = 1; k < model.keyframes; ++k) {
        std::vector<glm::dvec3> movement;
        for (std::size_t i = 0; i < examples.size(); ++i) movement.push_back(poseOf(i, 0, k).positionMm - poseOf(i, 0, 0).positionMm);
        model.vector.rightMovement.push_back(fitVector3(model.basis, inputs, movement, options.ridge));
    }
    if (model.hands > 1) {
        for (std::size_t k = 0; k < model.keyframes; ++k) {
            std::vector<glm::dvec3> relative;
            for (std::size_t i = 0; i < examples.size(); ++i) relative.push_back(poseOf(i, 1, k).positionMm - poseOf(i, 0, k).positionMm);
            model.vector.leftRelative.push_back(fitVector3(model.basis, inputs, relative, options.ridge));
        }
    }
    // SPEC §3.5 [D]: the mixture is fitted to points along the recorded right-hand paths, so
    // that it models where the hand travels, which is what the start search scores.
    std::vector<glm::dvec3> locations;
    for (std::size_t i = 0; i < examples.size(); ++i) {
        std::vector<glm::dvec3> keyPositions;
        for (std::size_t k = 0; k < model.keyframes; ++k) keyPositions.push_back(poseOf(i, 0, k).positionMm);
        for (const glm::dvec3& p : pathSamples(keyPositions)) locations.push_back(p);
    }
    model.vector.rightLocation = fitGaussianMixtureByBic(locations, options.mixture).mixture;
    model.vector.searchMinMm = glm::dvec3(std::numeric_limits<double>::infinity());
    model.vector.searchMaxMm = -model.vector.searchMinMm;
    for (const glm::dvec3& p : locations) {
        model.vector.searchMinMm = glm::min(model.vector.searchMinMm, p);
        model.vector.searchMaxMm = glm::max(model.vector.searchMaxMm, p);
    }
    return model;
}

TrainedVerbModels trainVerbModels(const Corpus& corpus, const VerbLibrary& verbs, const ModelOptions& options) {
    TrainedVerbModels models;
    models.sourceFile = corpus.sourceFile;
    models.corpusDescription = std::filesystem::path(corpus.sourceFile).filename().string();
    if (!corpus.comments.empty()) {
        std::string first = corpus.comments.front();
        while (!first.empty() && first.front() == ' ') first.erase(first.begin());
        models.corpusDescription += ": " + first;
    }
    for (const VerbDefinition& verb : verbs.verbs) {
        const std::vector<const CorpusExample*> examples = corpus.examplesOf(verb.name);
        if (examples.empty()) continue;
        try {
            models.verbs.push_back(trainVerbModel(verb, examples, options));
        } catch (const InputError& e) {
            throw InputError(corpus.sourceFile, examples.front()->firstLine, "verb", e.detail());
        }
    }
    return models;
}

std::vector<std::vector<HandPose>> predictPoint(const VerbModel& model, double subject, double object) {
    std::vector<std::vector<HandPose>> poses(model.hands, std::vector<HandPose>(model.keyframes));
    for (std::size_t h = 0; h < model.hands; ++h)
        for (std::size_t k = 0; k < model.keyframes; ++k)
            poses[h][k] = HandPose{model.point.position[h][k](subject, object),
                                   model.orientation.predict(h, k, subject, object)};
    return poses;
}

glm::dvec3 mostLikelyStart(const GaussianMixture& mixture, const glm::dvec3& boxMin, const glm::dvec3& boxMax,
                           const std::vector<glm::dvec3>& offsets) {
    const std::vector<glm::dvec3> samples = pathSamples(offsets);
    std::vector<glm::dvec3> points(samples.size());
    const auto score = [&](const glm::dvec3& start) {
        for (std::size_t j = 0; j < samples.size(); ++j) points[j] = start + samples[j];
        return mixture.sumLogDensity(points);
    };
    // The path must fit in the box as far as possible: search the starts that keep the whole
    // path inside the box when it is small enough, else the whole box.
    glm::dvec3 low = boxMin;
    glm::dvec3 high = boxMax;
    glm::dvec3 offsetMin(0.0), offsetMax(0.0);
    for (const glm::dvec3& o : samples) {
        offsetMin = glm::min(offsetMin, o);
        offsetMax = glm::max(offsetMax, o);
    }
    for (int a = 0; a < 3; ++a) {
        if (boxMin[a] - offsetMin[a] <= boxMax[a] - offsetMax[a]) {
            low[a] = boxMin[a] - offsetMin[a];
            high[a] = boxMax[a] - offsetMax[a];
        }
    }
    constexpr int kGrid = 9;
    glm::dvec3 best = 0.5 * (low + high);
    double bestScore = score(best);
    for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j < kGrid; ++j)
            for (int k = 0; k < kGrid; ++k) {
                const glm::dvec3 t(i / double(kGrid - 1), j / double(kGrid - 1), k / double(kGrid - 1));
                const glm::dvec3 candidate = low + t * (high - low);
                const double s = score(candidate);
                if (s > bestScore) {
                    bestScore = s;
                    best = candidate;
                }
            }
    glm::dvec3 step = glm::max((high - low) / double(kGrid - 1), glm::dvec3(1.0));
    while (step.x > 0.01 || step.y > 0.01 || step.z > 0.01) {
        bool improved = false;
        for (int a = 0; a < 3; ++a)
            for (double sign : {1.0, -1.0}) {
                glm::dvec3 candidate = best;
                candidate[a] += sign * step[a];
                const double s = score(candidate);
                if (s > bestScore) {
                    bestScore = s;
                    best = candidate;
                    improved = true;
                }
            }
        if (!improved) step *= 0.5;
    }
    return best;
}

std::vector<std::vector<HandPose>> predictVector(const VerbModel& model, double subject, double object) {
    std::vector<glm::dvec3> offsets{glm::dvec3(0.0)};
    for (const Vector3Polynomial& movement : model.vector.rightMovement) offsets.push_back(movement(subject, object));
    const glm::dvec3 start =
        mostLikelyStart(model.vector.rightLocation, model.vector.searchMinMm, model.vector.searchMaxMm, offsets);
    std::vector<std::vector<HandPose>> poses(model.hands, std::vector<HandPose>(model.keyframes));
    for (std::size_t k = 0; k < model.keyframes; ++k) {
        poses[0][k] = HandPose{start + offsets[k], model.orientation.predict(0, k, subject, object)};
        if (model.hands > 1)
            poses[1][k] = HandPose{poses[0][k].positionMm + model.vector.leftRelative[k](subject, object),
                                   model.orientation.predict(1, k, subject, object)};
    }
    return poses;
}

std::string formatVerbModels(const TrainedVerbModels& models) {
    Json root = Json::object();
    root["format"] = "signstim-verb-models";
    root["version"] = 1;
    root["about"] = "PointModel, VectorModel and SORA orientation model per verb (SPEC 3.4-3.6), trained by "
                    "`signstim train`. Positions in mm, signing-space frame; SORA in radians relative to the mean "
                    "rotation [w, x, y, z]; polynomial terms [1, s, o, s^2, so, o^2, s^3, s^2o, so^2, o^3] or "
                    "[1, o, o^2, o^3] (object-only verbs).";
    root["trainedOn"] = models.corpusDescription;
    Json verbs = Json::array();
    for (const VerbModel& model : models.verbs) {
        Json v = Json::object();
        v["verb"] = model.verb;
        v["inflects"] = toString(model.basis.inflection);
        v["degree"] = model.basis.degree;
        v["hands"] = model.hands;
        v["keyframes"] = model.keyframes;
        v["trainingExamples"] = model.trainingExamples;
        Json point = Json::array();
        Json orientation = Json::array();
        for (std::size_t h = 0; h < model.hands; ++h) {
            Json pointHand = Json::array();
            Json orientationHand = Json::array();
            for (std::size_t k = 0; k < model.keyframes; ++k) {
                pointHand.push_back(polyJson(model.point.position[h][k]));
                Json o = Json::object();
                o["mean"] = quatJson(model.orientation.mean[h][k]);
                o["sora"] = polyJson(model.orientation.relativeSora[h][k]);
                orientationHand.push_back(o);
            }
            point.push_back(pointHand);
            orientation.push_back(orientationHand);
        }
        v["point"] = point;
        v["orientation"] = orientation;
        Json vector = Json::object();
        Json movement = Json::array();
        for (const auto& p : model.vector.rightMovement) movement.push_back(polyJson(p));
        vector["rightMovement"] = movement;
        Json relative = Json::array();
        for (const auto& p : model.vector.leftRelative) relative.push_back(polyJson(p));
        vector["leftRelative"] = relative;
        Json components = Json::array();
        for (const GaussianComponent& c : model.vector.rightLocation.components) {
            Json component = Json::object();
            component["weight"] = rounded(c.weight);
            component["meanMm"] = vec3Json(c.meanMm);
            Json covariance = Json::array();
            for (int r = 0; r < 3; ++r) covariance.push_back(numbers({c.covarianceMm2[0][r], c.covarianceMm2[1][r], c.covarianceMm2[2][r]}));
            component["covarianceMm2"] = covariance;
            components.push_back(component);
        }
        vector["rightLocation"] = components;
        vector["searchBoxMm"] = Json::array({vec3Json(model.vector.searchMinMm), vec3Json(model.vector.searchMaxMm)});
        v["vector"] = vector;
        verbs.push_back(v);
    }
    root["verbs"] = verbs;
    return root.dump(1) + "\n";
}

namespace {

struct ModelReader {
    const JsonSource& source;
    std::vector<std::string> anchors;
    std::string pointer;

    [[noreturn]] void fail(const std::string& field, const std::string& message) const {
        source.fail(anchors, pointer + field, message + " (regenerate the file with `signstim train`)");
    }
    std::vector<double> numbersOf(const nlohmann::json& value, std::size_t count, const std::string& field,
                                  const NumberRange& range) const {
        if (!value.is_array() || value.size() != count) fail(field, "expected " + std::to_string(count) + " numbers");
        std::vector<double> result;
        for (std::size_t i = 0; i < value.size(); ++i) {
            if (!value[i].is_number()) fail(field, "expected numbers");
            const double number = value[i].get<double>();
            const std::string element = pointer + field + "/" + std::to_string(i);
            if (!range.contains(number))
                source.failAt(element, rangeMessage(range.minimum, range.maximum, range.unit, number) +
                                           " (regenerate the file with `signstim train`)");
            result.push_back(number);
        }
        return result;
    }
    Vector3Polynomial poly(const nlohmann::json& value, const PolynomialBasis& basis, const std::string& field) const {
        if (!value.is_object() || !value.contains("x") || !value.contains("y") || !value.contains("z"))
            fail(field, "expected {\"x\": [...], \"y\": [...], \"z\": [...]}");
        const std::size_t n = basis.termCount();
        return {Polynomial{basis, numbersOf(value["x"], n, field + "/x", kModelCoefficientRange)},
                Polynomial{basis, numbersOf(value["y"], n, field + "/y", kModelCoefficientRange)},
                Polynomial{basis, numbersOf(value["z"], n, field + "/z", kModelCoefficientRange)}};
    }
    const nlohmann::json& at(const nlohmann::json& object, const std::string& key, const std::string& field) const {
        if (!object.is_object() || !object.contains(key)) fail(field + "/" + key, "missing field '" + key + "'");
        return object[key];
    }
};

}  // namespace

TrainedVerbModels parseVerbModels(const JsonSource& source, const VerbLibrary& verbs) {
    return withJsonErrors(source, [&] {
    const nlohmann::json& root = source.root;
    if (!root.is_object() || root.value("format", "") != "signstim-verb-models")
        source.fail({"\"format\""}, "/format", "not a signstim verb-models file (\"format\": \"signstim-verb-models\")");
    source.checkFormat("signstim-verb-models", 1);
    TrainedVerbModels models;
    models.sourceFile = source.file;
    models.corpusDescription = root.value("trainedOn", "");
    if (!root.contains("verbs") || !root["verbs"].is_array()) source.fail({"\"verbs\""}, "/verbs", "expected an array");
    for (std::size_t i = 0; i < root["verbs"].size(); ++i) {
        const nlohmann::json& v = root["verbs"][i];
        ModelReader reader{source, {"\"verbs\""}, "/verbs/" + std::to_string(i)};
        if (!v.is_object() || !v.contains("verb") || !v["verb"].is_string()) reader.fail("/verb", "missing verb name");
        VerbModel model;
        model.verb = v["verb"].get<std::string>();
        model.sourceLine = source.lineAt(reader.pointer);
        reader.anchors.push_back("\"" + model.verb + "\"");
        const VerbDefinition& verb = verbs.get(model.verb, source.file, source.lineAt(reader.pointer + "/verb"), reader.pointer + "/verb");
        const int degree = reader.at(v, "degree", "").is_number_integer() ? v["degree"].get<int>() : -1;
        if (degree < 0 || degree > 3) reader.fail("/degree", "expected 0..3");
        model.basis = PolynomialBasis{verb.inflection, degree};
        if (v.value("inflects", "") != toString(verb.inflection) || v.value("hands", 0u) != verb.handCount() ||
            v.value("keyframes", 0u) != verb.keyframeCount())
            reader.fail("", "the model of " + verb.name + " does not match scenes/verbs.json (class, hands or keyframes)");
        model.hands = verb.handCount();
        model.keyframes = verb.keyframeCount();
        model.trainingExamples = v.value("trainingExamples", 0u);
        const nlohmann::json& point = reader.at(v, "point", "");
        const nlohmann::json& orientation = reader.at(v, "orientation", "");
        if (!point.is_array() || point.size() != model.hands || !orientation.is_array() || orientation.size() != model.hands)
            reader.fail("/point", "expected one entry per hand");
        model.point.position.resize(model.hands);
        model.orientation.mean.resize(model.hands);
        model.orientation.relativeSora.resize(model.hands);
        for (std::size_t h = 0; h < model.hands; ++h) {
            if (!point[h].is_array() || point[h].size() != model.keyframes || !orientation[h].is_array() ||
                orientation[h].size() != model.keyframes)
                reader.fail("/point/" + std::to_string(h), "expected one entry per keyframe");
            for (std::size_t k = 0; k < model.keyframes; ++k) {
                const std::string where = "/" + std::to_string(h) + "/" + std::to_string(k);
                model.point.position[h].push_back(reader.poly(point[h][k], model.basis, "/point" + where));
                const std::vector<double> q = reader.numbersOf(reader.at(orientation[h][k], "mean", "/orientation" + where), 4,
                                                               "/orientation" + where + "/mean", NumberRange{-1.0, 1.0, ""});
                const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
                if (std::abs(norm - 1.0) > 1e-3)
                    reader.fail("/orientation" + where + "/mean", "expected a unit quaternion [w, x, y, z] (length " +
                                                                       formatNumber(norm) + ")");
                model.orientation.mean[h].push_back(glm::normalize(glm::dquat(q[0], q[1], q[2], q[3])));
                model.orientation.relativeSora[h].push_back(
                    reader.poly(reader.at(orientation[h][k], "sora", "/orientation" + where), model.basis, "/orientation" + where + "/sora"));
            }
        }
        const nlohmann::json& vector = reader.at(v, "vector", "");
        const nlohmann::json& movement = reader.at(vector, "rightMovement", "/vector");
        if (!movement.is_array() || movement.size() != model.keyframes - 1) reader.fail("/vector/rightMovement", "expected keyframes − 1 entries");
        for (std::size_t k = 0; k + 1 < model.keyframes; ++k)
            model.vector.rightMovement.push_back(reader.poly(movement[k], model.basis, "/vector/rightMovement/" + std::to_string(k)));
        const nlohmann::json& relative = reader.at(vector, "leftRelative", "/vector");
        if (!relative.is_array() || relative.size() != (model.hands > 1 ? model.keyframes : 0))
            reader.fail("/vector/leftRelative", "expected one entry per keyframe for two-handed verbs");
        for (std::size_t k = 0; k < relative.size(); ++k)
            model.vector.leftRelative.push_back(reader.poly(relative[k], model.basis, "/vector/leftRelative/" + std::to_string(k)));
        const nlohmann::json& components = reader.at(vector, "rightLocation", "/vector");
        if (!components.is_array() || components.empty()) reader.fail("/vector/rightLocation", "expected mixture components");
        for (std::size_t c = 0; c < components.size(); ++c) {
            const std::string where = "/vector/rightLocation/" + std::to_string(c);
            GaussianComponent component;
            const nlohmann::json& weight = reader.at(components[c], "weight", where);
            if (!weight.is_number() || !(weight.get<double>() > 0.0) || !(weight.get<double>() <= 1.0))
                reader.fail(where + "/weight", "expected a weight in (0, 1]" +
                                                   (weight.is_number() ? ", got " + formatNumber(weight.get<double>()) : std::string()));
            component.weight = weight.get<double>();
            const std::vector<double> m = reader.numbersOf(reader.at(components[c], "meanMm", where), 3, where + "/meanMm",
                                                         kSigningSpacePositionRange);
            component.meanMm = glm::dvec3(m[0], m[1], m[2]);
            const nlohmann::json& covariance = reader.at(components[c], "covarianceMm2", where);
            if (!covariance.is_array() || covariance.size() != 3) reader.fail(where + "/covarianceMm2", "expected a 3×3 matrix");
            for (int r = 0; r < 3; ++r) {
                const std::vector<double> row = reader.numbersOf(covariance[static_cast<std::size_t>(r)], 3,
                                                          where + "/covarianceMm2/" + std::to_string(r), kCovarianceRange);
                for (int col = 0; col < 3; ++col) component.covarianceMm2[col][r] = row[static_cast<std::size_t>(col)];
            }
            model.vector.rightLocation.components.push_back(component);
        }
        try {
            (void)model.vector.rightLocation.logDensity(model.vector.rightLocation.components.front().meanMm);
        } catch (const std::invalid_argument&) {
            reader.fail("/vector/rightLocation", "a covariance is not positive definite");
        }
        const nlohmann::json& box = reader.at(vector, "searchBoxMm", "/vector");
        if (!box.is_array() || box.size() != 2) reader.fail("/vector/searchBoxMm", "expected [[min], [max]]");
        const std::vector<double> lo = reader.numbersOf(box[0], 3, "/vector/searchBoxMm/0", kSigningSpacePositionRange);
        const std::vector<double> hi = reader.numbersOf(box[1], 3, "/vector/searchBoxMm/1", kSigningSpacePositionRange);
        for (int axis = 0; axis < 3; ++axis)
            if (!(lo[static_cast<std::size_t>(axis)] <= hi[static_cast<std::size_t>(axis)]))
                reader.fail("/vector/searchBoxMm", "the box's minimum exceeds its maximum");
        model.vector.searchMinMm = glm::dvec3(lo[0], lo[1], lo[2]);
        model.vector.searchMaxMm = glm::dvec3(hi[0], hi[1], hi[2]);
        if (models.find(model.verb)) reader.fail("/verb", "verb " + model.verb + " appears twice");
        models.verbs.push_back(std::move(model));
    }
    return models;
    });
}

std::string formatCheckedVerbModels(const TrainedVerbModels& models, const VerbLibrary& verbs,
                                    const std::string& outputName) {
    std::string text = formatVerbModels(models);
    try {
        (void)parseVerbModels(parseJsonText(text, outputName), verbs);
    } catch (const InputError& e) {
        // The corpus is what the user can fix; the model's field says where it went wrong.
        throw InputError(models.sourceFile, 0, e.field(),
                         "the models trained on this corpus would not load back, so " + outputName +
                             " is not written: " + e.detail());
    }
    return text;
}

TrainedVerbModels loadVerbModels(const std::filesystem::path& path, const VerbLibrary& verbs) {
    return parseVerbModels(readJsonFile(path), verbs);
}

}  // namespace signstim::stimuli
