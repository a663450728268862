#pragma once
// Builds small glTF files for the tests by hand (JSON + binary), so the loader is checked
// against files not produced by our own writer. No downloaded assets.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace signstim::render::testing {

// An empty folder for the running test: build/test-tmp/AREA/Suite.Name.
inline std::filesystem::path freshTestDir(const std::string& area) {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::filesystem::path dir = std::filesystem::path(SIGNSTIM_BINARY_DIR) / "test-tmp" / area /
                                      (std::string(info->test_suite_name()) + "." + info->name());
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::string base64(const std::vector<std::uint8_t>& data) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < data.size(); i += 3) {
        const std::uint32_t v = (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
        for (int s = 18; s >= 0; s -= 6) out += table[(v >> s) & 63];
    }
    if (i + 1 == data.size()) {
        const std::uint32_t v = data[i] << 16;
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += "==";
    } else if (i + 2 == data.size()) {
        const std::uint32_t v = (data[i] << 16) | (data[i + 1] << 8);
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += table[(v >> 6) & 63];
        out += '=';
    }
    return out;
}

enum class Container { ExternalBuffer, Embedded, Glb };

// A glTF document under construction: one binary buffer that views point into.
struct GltfBuilder {
    nlohmann::json doc = {{"asset", {{"version", "2.0"}}}};
    std::vector<std::uint8_t> bin;

    template <typename T>
    int addView(const std::vector<T>& values, int byteStride = 0) {
        while (bin.size() % 4) bin.push_back(0);
        const std::size_t offset = bin.size();
        bin.resize(offset + values.size() * sizeof(T));
        std::memcpy(bin.data() + offset, values.data(), values.size() * sizeof(T));
        nlohmann::json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(T)}};
        if (byteStride) view["byteStride"] = byteStride;
        doc["bufferViews"].push_back(view);
        return static_cast<int>(doc["bufferViews"].size()) - 1;
    }
    int addAccessor(int view, int componentType, std::size_t count, const char* type,
                    bool normalized = false, std::size_t byteOffset = 0) {
        nlohmann::json a = {{"bufferView", view}, {"componentType", componentType}, {"count", count}, {"type", type}};
        if (normalized) a["normalized"] = true;
        if (byteOffset) a["byteOffset"] = byteOffset;
        doc["accessors"].push_back(a);
        return static_cast<int>(doc["accessors"].size()) - 1;
    }
    int addFloats(const std::vector<float>& values, const char* type, std::size_t components) {
        return addAccessor(addView(values), 5126, values.size() / components, type);
    }

    // Writes `dir/name` (+ `name`.bin for ExternalBuffer); returns the glTF path.
    std::filesystem::path write(const std::filesystem::path& dir, const std::string& name, Container container) {
        std::filesystem::create_directories(dir);
        nlohmann::json out = doc;
        while (bin.size() % 4) bin.push_back(0);
        if (!bin.empty()) {
            out["buffers"] = nlohmann::json::array();
            nlohmann::json buffer = {{"byteLength", bin.size()}};
            if (container == Container::ExternalBuffer) {
                buffer["uri"] = name + ".bin";
                std::ofstream(dir / (name + ".bin"), std::ios::binary)
                    .write(reinterpret_cast<const char*>(bin.data()), static_cast<std::streamsize>(bin.size()));
            } else if (container == Container::Embedded) {
                buffer["uri"] = "data:application/octet-stream;base64," + base64(bin);
            }
            out["buffers"].push_back(buffer);
        }
        const std::filesystem::path path = dir / name;
        std::ofstream file(path, std::ios::binary);
        if (container != Container::Glb) {
            file << out.dump(1);
            return path;
        }
        std::string json = out.dump();
        while (json.size() % 4) json += ' ';
        const std::uint32_t total = static_cast<std::uint32_t>(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size()));
        auto u32 = [&](std::uint32_t v) { file.write(reinterpret_cast<const char*>(&v), 4); };
        u32(0x46546C67);
        u32(2);
        u32(total);
        u32(static_cast<std::uint32_t>(json.size()));
        u32(0x4E4F534A);
        file.write(json.data(), static_cast<std::streamsize>(json.size()));
        if (!bin.empty()) {
            u32(static_cast<std::uint32_t>(bin.size()));
            u32(0x004E4942);
            file.write(reinterpret_cast<const char*>(bin.data()), static_cast<std::streamsize>(bin.size()));
        }
        return path;
    }
};

// One triangle in the XY plane (normal +Z) with indices; node 0 shows mesh 0.
inline GltfBuilder triangleGltf() {
    GltfBuilder b;
    const int positions = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
    const int indices = b.addAccessor(b.addView(std::vector<std::uint16_t>{0, 1, 2}), 5123, 3, "SCALAR");
    b.doc["meshes"] = {{{"name", "triangle"},
                        {"primitives", {{{"attributes", {{"POSITION", positions}}}, {"indices", indices}}}}}};
    b.doc["nodes"] = {{{"name", "tri"}, {"mesh", 0}}};
    b.doc["scenes"] = {{{"nodes", {0}}}};
    b.doc["scene"] = 0;
    return b;
}

// triangleGltf() with one animation "slide": node 0's translation x = key time at each of
// `times` (LINEAR). Accessors: 0 positions, 1 indices, 2 key times, 3 translations.
inline GltfBuilder animatedTriangleGltf(const std::vector<float>& times) {
    GltfBuilder b = triangleGltf();
    const int input = b.addFloats(times, "SCALAR", 1);
    std::vector<float> translations;
    for (float t : times) translations.insert(translations.end(), {t, 0.0f, 0.0f});
    const int output = b.addFloats(translations, "VEC3", 3);
    b.doc["animations"] = {{{"name", "slide"},
                            {"samplers", {{{"input", input}, {"output", output}, {"interpolation", "LINEAR"}}}},
                            {"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}}}};
    return b;
}

}  // namespace signstim::render::testing
