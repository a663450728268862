// Fuzz targets of glTF 2.0 models (render-gltf, a lab's own avatar): the validator alone
// (renderer/gltf_validate.hpp), with every accessor read through its checked reader, and the
// whole load (validation, then conversion into a Scene). Inputs are taken as the file
// "model.gltf" in an empty folder, so external URIs are refused or not found, never read
// from elsewhere.
#include "common/error.hpp"
#include "renderer/gltf_loader.hpp"
#include "renderer/gltf_validate.hpp"
#include "tests/fuzz/fixtures.hpp"
#include "tests/fuzz/fuzz_target.hpp"

#include <tiny_gltf.h>

#include <cstdlib>
#include <filesystem>

namespace {

const std::filesystem::path& emptyFolder() {
    static const std::filesystem::path folder = [] {
        std::string pattern = (std::filesystem::temp_directory_path() / "signstim-fuzz-gltf.XXXXXX").string();
        if (!mkdtemp(pattern.data())) signstim::fuzz::fail("cannot make a temporary folder");
        return std::filesystem::path(pattern);
    }();
    return folder;
}

}  // namespace

using namespace signstim;
using signstim::fuzz::expectRefusalOrSuccess;
using signstim::fuzz::requireFinite;

SIGNSTIM_FUZZ_TARGET(gltf_validate) {
    expectRefusalOrSuccess("model.gltf", [&] {
        const render::ValidatedGltf gltf =
            render::validateGltfBytes(std::string(input), "model.gltf", emptyFolder(), render::GltfLoadOptions{});
        // Every accessor through the checked reader, as the type it declares: refusals are
        // InputErrors, and what it returns is finite.
        for (std::size_t i = 0; i < gltf.model().accessors.size(); ++i) {
            try {
                const int type = gltf.model().accessors[i].type;
                for (double v : gltf.readAccessor(static_cast<int>(i), {type}, {}, "/fuzz")) requireFinite(v, "accessor value");
            } catch (const InputError& e) {
                if (e.file() != "model.gltf") fuzz::fail(std::string("an accessor refusal names another file: ") + e.what());
            }
        }
    });
}

SIGNSTIM_FUZZ_TARGET(gltf_load) {
    expectRefusalOrSuccess("model.gltf", [&] {
        std::vector<std::string> warnings;
        const render::Scene scene =
            render::loadGltfBytes(std::string(input), "model.gltf", emptyFolder(), render::GltfLoadOptions{}, &warnings);
        for (const render::Mesh& mesh : scene.meshes)
            for (const render::Primitive& primitive : mesh.primitives) {
                for (std::uint32_t index : primitive.indices)
                    if (index >= primitive.vertices.size()) fuzz::fail("an index past the vertices accepted");
                for (const render::Vertex& vertex : primitive.vertices)
                    for (int k = 0; k < 3; ++k) requireFinite(vertex.position[k], "vertex position");
                // Morph targets: one per mesh target, dense over the vertices, finite.
                if (primitive.targets.size() != mesh.targetCount()) fuzz::fail("primitives with different target counts accepted");
                for (const render::MorphTarget& target : primitive.targets)
                    for (const auto* attribute : {&target.position, &target.normal}) {
                        if (!attribute->empty() && attribute->size() != primitive.vertices.size())
                            fuzz::fail("a morph target not covering every vertex accepted");
                        for (const glm::vec3& d : *attribute)
                            for (int k = 0; k < 3; ++k) requireFinite(d[k], "morph displacement");
                    }
            }
        // Pose every animation (weights channels included) at its middle; weights stay finite.
        for (std::size_t a = 0; a < scene.animations.size(); ++a) {
            render::Pose pose = render::restPose(scene);
            render::applyAnimation(scene, static_cast<int>(a), 0.5f * scene.animations[a].durationSeconds, pose);
            for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
                const std::vector<float> weights = render::resolveMorphWeights(scene, pose, static_cast<int>(n));
                for (float w : weights) requireFinite(w, "morph weight");
            }
        }
    });
}
