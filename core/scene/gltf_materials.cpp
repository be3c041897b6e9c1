// glTF materials and textures: metal-rough factors, images decoded to RGBA8 (in parallel,
// only those a material uses), one tp::Texture per (image, sRGB) pair, placeholders for
// images that cannot be had.
#include <algorithm>
#include <cmath>
#include <map>

#include "core/scene/gltf_internal.h"
#include "core/util/parallel.h"

namespace tp::gltf {
namespace {

enum class Slot { BaseColor, MetallicRoughness, Normal, Occlusion, Emissive };

bool isSrgb(Slot slot) {
    return slot == Slot::BaseColor || slot == Slot::Emissive;
}

// What stands in for an image that cannot be had: conspicuous magenta for base colour; no
// emission (black) rather than a magenta glow; a flat normal; white (factors unchanged) for
// metal-rough and occlusion.
Texture placeholder(Slot slot) {
    Texture t;
    t.width = t.height = 1;
    t.srgb = isSrgb(slot);
    switch (slot) {
    case Slot::BaseColor:
        t.rgba8 = {255, 0, 255, 255}, t.name = "placeholder:baseColor";
        break;
    case Slot::Emissive:
        t.rgba8 = {0, 0, 0, 255}, t.name = "placeholder:emissive";
        break;
    case Slot::Normal:
        t.rgba8 = {128, 128, 255, 255}, t.name = "placeholder:normal";
        break;
    default:
        t.rgba8 = {255, 255, 255, 255}, t.name = "placeholder:white";
        break;
    }
    return t;
}

struct Decoded {
    std::vector<uint8_t> rgba8;
    int width = 0, height = 0;
    std::string problem; // why there is no image (a placeholder is used)
    bool tooLarge = false;
};

// `image` holds the encoded file (as_is) as our image loader left it, or decoded pixels when
// tinygltf decoded them itself.
Decoded decode(const tinygltf::Image& image, int index) {
    Decoded d;
    if (!image.as_is) {
        d.width = image.width, d.height = image.height;
        if (!toRgba8(image.image.data(), image.image.size(), image.width, image.height,
                     image.component, image.bits, d.rgba8))
            d.problem = "decoded pixels have an unsupported layout";
        return d;
    }
    const unsigned char* bytes = image.image.data();
    size_t size = image.image.size();
    // Only PNG and JPEG (all that glTF 2.0 allows) and only after their headers are checked:
    // stb would decode other formats, and sizes up to 2^24, with int arithmetic.
    if (!peekImageSize(bytes, size, d.width, d.height)) {
        d.problem = "not a PNG or JPEG image, or its header is damaged";
        return d;
    }
    bool png16 = size > 24 && bytes[0] == 0x89 && bytes[24] == 16;
    if (d.width > kMaxTextureSide || d.height > kMaxTextureSide ||
        (png16 && uint64_t(d.width) * uint64_t(d.height) >= (1ull << 28))) {
        d.tooLarge = true;
        return d;
    }
    std::vector<unsigned char> cleaned; // the PNG without its empty IDAT chunks, when it has some
    if (bytes[0] == 0x89) {
        if (std::string problem = checkPng(bytes, size, cleaned); !problem.empty()) {
            d.problem = "refused before decoding: " + problem;
            return d;
        }
        if (!cleaned.empty()) bytes = cleaned.data(), size = cleaned.size();
    }
    tinygltf::Image pixels;
    std::string err, warn;
    if (size > size_t(INT32_MAX) ||
        !tinygltf::LoadImageData(&pixels, index, &err, &warn, 0, 0, bytes, int(size), nullptr)) {
        d.problem = "cannot decode: " + firstLine(err);
        return d;
    }
    d.width = pixels.width, d.height = pixels.height;
    if (!toRgba8(pixels.image.data(), pixels.image.size(), pixels.width, pixels.height,
                 pixels.component, pixels.bits, d.rgba8))
        d.problem = "decoded pixels have an unsupported layout";
    return d;
}

// Runs decode() over `needed` on the cores (stb and tinygltf's LoadImageData keep no shared
// state between calls); forEachInParallel falls back to fewer threads if they cannot be had.
void decodeAll(const tinygltf::Model& model, const std::vector<int>& needed,
               std::vector<Decoded>& decoded) {
    forEachInParallel(needed.size(), [&](size_t k) {
        decoded[size_t(needed[k])] = decode(model.images[size_t(needed[k])], needed[k]);
    });
}

std::string imageLabel(const tinygltf::Model& model, int index) {
    const tinygltf::Image& image = model.images[size_t(index)];
    std::string label = "image " + std::to_string(index);
    if (!image.uri.empty() && image.uri.rfind("data:", 0) != 0)
        label += " '" + image.uri + "'";
    else if (!image.name.empty())
        label += " ('" + image.name + "')";
    return label;
}

std::string tooLargeError(const tinygltf::Model& model, int index, int width, int height) {
    return imageLabel(model, index) + " is " + std::to_string(width) + "x" +
           std::to_string(height) + ", over the " + std::to_string(kMaxTextureSide) + " limit";
}

// From the headers, before anything is decoded (a PNG header is 33 bytes; what it claims
// would be allocated by the decoder): every side within kMaxTextureSide, and all the images
// together within kMaxTexturePixels. An unreadable header is skipped here: that image becomes
// a placeholder.
Status checkTextureSizes(const tinygltf::Model& model, const std::vector<int>& toDecode) {
    uint64_t total = 0;
    for (int i : toDecode) {
        const tinygltf::Image& image = model.images[size_t(i)];
        int w = image.width, h = image.height;
        if (image.as_is && !peekImageSize(image.image.data(), image.image.size(), w, h)) continue;
        if (w <= 0 || h <= 0) continue;
        if (w > kMaxTextureSide || h > kMaxTextureSide) return Error{tooLargeError(model, i, w, h)};
        total += uint64_t(w) * uint64_t(h);
    }
    if (total > kMaxTexturePixels)
        return Error{"the textures add up to " + std::to_string(total) + " pixels, over the 2^" +
                     std::to_string(kMaxTexturePixelsLog2) + " limit (" +
                     std::to_string(kMaxTexturePixels >> 28) + " GiB as RGBA8)"};
    return {};
}


// Which image each texture slot of a material shows.
std::vector<std::pair<int, Slot>> slotsOf(const tinygltf::Material& m) {
    const auto& pbr = m.pbrMetallicRoughness;
    return {{pbr.baseColorTexture.index, Slot::BaseColor},
            {pbr.metallicRoughnessTexture.index, Slot::MetallicRoughness},
            {m.normalTexture.index, Slot::Normal},
            {m.occlusionTexture.index, Slot::Occlusion},
            {m.emissiveTexture.index, Slot::Emissive}};
}

// The image a texture shows (-1: none or unusable).
int imageOf(const tinygltf::Model& model, int texture) {
    if (texture < 0 || size_t(texture) >= model.textures.size()) return -1;
    int source = model.textures[size_t(texture)].source;
    return source >= 0 && size_t(source) < model.images.size() ? source : -1;
}

// Per image: whether a material shows it, and how many distinct sRGB flags it is shown with.
struct ImageUse {
    std::vector<char> needed;
    std::vector<int> flavoursLeft; // distinct sRGB flags still to create
};

ImageUse imageUses(const tinygltf::Model& model) {
    ImageUse use{std::vector<char>(model.images.size(), 0),
                 std::vector<int>(model.images.size(), 0)};
    std::vector<char> seen(model.images.size() * 2, 0);
    for (const tinygltf::Material& m : model.materials)
        for (auto [texture, slot] : slotsOf(m))
            if (int image = imageOf(model, texture); image >= 0) {
                use.needed[size_t(image)] = 1;
                char& s = seen[size_t(image) * 2 + (isSrgb(slot) ? 1 : 0)];
                if (!s) ++use.flavoursLeft[size_t(image)];
                s = 1;
            }
    return use;
}

// Decodes the images a material shows and the loader could read; warns of every image
// without pixels (its problem from the loader or the decoder).
Status decodeImages(const tinygltf::Model& model, const std::vector<std::string>& imageProblems,
                    const std::vector<char>& needed, std::vector<Decoded>& decoded,
                    const WarnFn& warn) {
    std::vector<int> toDecode;
    for (size_t i = 0; i < needed.size(); ++i)
        if (needed[i] && (i >= imageProblems.size() || imageProblems[i].empty()))
            toDecode.push_back(int(i));
    if (Status s = checkTextureSizes(model, toDecode); !s) return s;
    decoded.assign(model.images.size(), Decoded{});
    decodeAll(model, toDecode, decoded);
    for (size_t i = 0; i < needed.size(); ++i) {
        if (i < imageProblems.size() && !imageProblems[i].empty())
            decoded[i].problem = imageProblems[i];
        if (decoded[i].tooLarge)
            return Error{tooLargeError(model, int(i), decoded[i].width, decoded[i].height)};
        if (!decoded[i].problem.empty())
            warn(imageLabel(model, int(i)) + ": " + decoded[i].problem +
                 (needed[i] ? "; using a placeholder" : " (no material uses it)"));
    }
    return {};
}

// The scene's textures, each made on first use: one per (image, sRGB) pair, one placeholder
// per slot for every texture without pixels.
class TextureTable {
  public:
    TextureTable(const tinygltf::Model& model, std::vector<Decoded>& decoded,
                 std::vector<int> flavoursLeft, Scene& scene, const WarnFn& warn)
        : model_(model), decoded_(decoded), flavoursLeft_(std::move(flavoursLeft)), scene_(scene),
          warn_(warn) {}

    int32_t resolve(size_t material, int texture, Slot slot) {
        if (texture < 0) return kNoTexture;
        int image = imageOf(model_, texture);
        if (image < 0 || !decoded_[size_t(image)].problem.empty()) {
            if (image < 0)
                warn_("material " + std::to_string(material) + ": texture " +
                      std::to_string(texture) +
                      " does not exist or has no image this loader can read; using a placeholder");
            auto [it, added] = placeholderOf_.try_emplace(slot, int32_t(scene_.textures.size()));
            if (added) scene_.textures.push_back(placeholder(slot));
            return it->second;
        }
        auto [it, added] =
            textureOf_.try_emplace({image, isSrgb(slot)}, int32_t(scene_.textures.size()));
        if (added) scene_.textures.push_back(makeTexture(image, isSrgb(slot)));
        return it->second;
    }

  private:
    Texture makeTexture(int image, bool srgb) {
        Decoded& d = decoded_[size_t(image)];
        Texture t;
        const tinygltf::Image& src = model_.images[size_t(image)];
        t.name = !src.name.empty() ? src.name : "image " + std::to_string(image);
        if (src.name.empty() && !src.uri.empty() && src.uri.rfind("data:", 0) != 0)
            t.name = src.uri;
        t.width = uint32_t(d.width), t.height = uint32_t(d.height);
        t.srgb = srgb;
        // The last texture made from an image takes its pixels; an earlier one copies them.
        if (--flavoursLeft_[size_t(image)] == 0)
            t.rgba8 = std::move(d.rgba8);
        else
            t.rgba8 = d.rgba8;
        return t;
    }

    const tinygltf::Model& model_;
    std::vector<Decoded>& decoded_;
    std::vector<int> flavoursLeft_;
    Scene& scene_;
    const WarnFn& warn_;
    std::map<std::pair<int, bool>, int32_t> textureOf_; // (image, srgb) -> scene texture
    std::map<Slot, int32_t> placeholderOf_;
};

// Material `index`'s factors, alpha mode and sidedness (its textures are set apart).
Material readFactors(const tinygltf::Material& src, size_t index, const WarnFn& warn) {
    const auto& pbr = src.pbrMetallicRoughness;
    Material m;
    m.name = src.name;
    if (pbr.baseColorFactor.size() == 4)
        m.baseColorFactor = glm::vec4(pbr.baseColorFactor[0], pbr.baseColorFactor[1],
                                      pbr.baseColorFactor[2], pbr.baseColorFactor[3]);
    m.metallicFactor = std::clamp(float(pbr.metallicFactor), 0.0f, 1.0f);
    m.roughnessFactor = std::clamp(float(pbr.roughnessFactor), 0.0f, 1.0f);
    if (src.emissiveFactor.size() == 3)
        m.emissiveFactor =
            glm::vec3(src.emissiveFactor[0], src.emissiveFactor[1], src.emissiveFactor[2]);
    if (auto it = src.extensions.find("KHR_materials_emissive_strength");
        it != src.extensions.end() && it->second.IsObject() && it->second.Has("emissiveStrength") &&
        it->second.Get("emissiveStrength").IsNumber())
        m.emissiveFactor *= float(it->second.Get("emissiveStrength").GetNumberAsDouble());
    m.normalScale = float(src.normalTexture.scale);
    m.occlusionStrength = float(src.occlusionTexture.strength);
    if (src.alphaMode == "MASK")
        m.alphaMode = AlphaMode::Mask;
    else if (src.alphaMode == "BLEND")
        m.alphaMode = AlphaMode::Blend;
    else if (src.alphaMode != "OPAQUE")
        warn("material " + std::to_string(index) + ": unknown alphaMode '" + src.alphaMode +
             "', drawn opaque");
    m.alphaCutoff = float(src.alphaCutoff);
    m.doubleSided = src.doubleSided;
    return m;
}

int32_t& textureSlot(Material& m, Slot slot) {
    switch (slot) {
    case Slot::BaseColor:
        return m.baseColorTexture;
    case Slot::MetallicRoughness:
        return m.metallicRoughnessTexture;
    case Slot::Normal:
        return m.normalTexture;
    case Slot::Occlusion:
        return m.occlusionTexture;
    case Slot::Emissive:
        break;
    }
    return m.emissiveTexture;
}

} // namespace

Status loadMaterials(const tinygltf::Model& model, const std::vector<std::string>& imageProblems,
                     Scene& scene, const WarnFn& warn) {
    // Pass 1: decode the images the materials show.
    ImageUse use = imageUses(model);
    std::vector<Decoded> decoded;
    if (Status s = decodeImages(model, imageProblems, use.needed, decoded, warn); !s) return s;

    // Pass 2: materials, creating textures on first use.
    TextureTable textures(model, decoded, std::move(use.flavoursLeft), scene, warn);
    bool warnedTexCoord = false;
    for (size_t i = 0; i < model.materials.size(); ++i) {
        const tinygltf::Material& src = model.materials[i];
        const auto& pbr = src.pbrMetallicRoughness;
        Material m = readFactors(src, i, warn);
        for (auto [texture, slot] : slotsOf(src))
            textureSlot(m, slot) = textures.resolve(i, texture, slot);
        int texCoord = std::max({pbr.baseColorTexture.texCoord,
                                 pbr.metallicRoughnessTexture.texCoord, src.normalTexture.texCoord,
                                 src.occlusionTexture.texCoord, src.emissiveTexture.texCoord});
        if (texCoord > 0 && !warnedTexCoord) {
            warnedTexCoord = true;
            warn("material " + std::to_string(i) + " uses TEXCOORD_" + std::to_string(texCoord) +
                 "; only TEXCOORD_0 is read");
        }
        UvTransform transform = materialUvTransform(src);
        if (!transform.problem.empty())
            warn("material " + std::to_string(i) + ": KHR_texture_transform " + transform.problem);
        if (transform.present && std::find(scene.extensions.begin(), scene.extensions.end(),
                                           kTextureTransform) == scene.extensions.end())
            scene.extensions.push_back(kTextureTransform);
        scene.materials.push_back(std::move(m));
    }
    return {};
}

namespace {

// The spec's matrix, T * R * S, as a 2x3 (column-major: three columns of two).
glm::mat3x2 transformOf(const tinygltf::Value& ext) {
    auto number = [&](const tinygltf::Value& v, float fallback) {
        return v.IsNumber() && std::isfinite(v.GetNumberAsDouble()) ? float(v.GetNumberAsDouble())
                                                                    : fallback;
    };
    auto pair = [&](const char* key, glm::vec2 fallback) {
        const tinygltf::Value& a = ext.Get(key);
        if (!a.IsArray() || a.ArrayLen() != 2) return fallback;
        return glm::vec2(number(a.Get(0), fallback.x), number(a.Get(1), fallback.y));
    };
    const glm::vec2 offset = pair("offset", glm::vec2(0.0f));
    const glm::vec2 scale = pair("scale", glm::vec2(1.0f));
    const float rotation = number(ext.Get("rotation"), 0.0f);
    const float c = std::cos(rotation), s = std::sin(rotation);
    // u' = offset.x + c * scale.x * u + s * scale.y * v; v' = offset.y - s * scale.x * u + c *
    // scale.y * v.
    return glm::mat3x2(glm::vec2(c * scale.x, -s * scale.x), glm::vec2(s * scale.y, c * scale.y),
                       offset);
}

} // namespace

UvTransform materialUvTransform(const tinygltf::Material& m) {
    const auto& pbr = m.pbrMetallicRoughness;
    const std::pair<const char*, const tinygltf::ExtensionMap*> slots[] = {
        {"baseColorTexture",
         pbr.baseColorTexture.index >= 0 ? &pbr.baseColorTexture.extensions : nullptr},
        {"metallicRoughnessTexture", pbr.metallicRoughnessTexture.index >= 0
                                         ? &pbr.metallicRoughnessTexture.extensions
                                         : nullptr},
        {"normalTexture", m.normalTexture.index >= 0 ? &m.normalTexture.extensions : nullptr},
        {"occlusionTexture",
         m.occlusionTexture.index >= 0 ? &m.occlusionTexture.extensions : nullptr},
        {"emissiveTexture", m.emissiveTexture.index >= 0 ? &m.emissiveTexture.extensions : nullptr},
    };
    UvTransform r;
    const char* first = nullptr;
    for (const auto& [name, extensions] : slots) {
        if (!extensions) continue;
        auto it = extensions->find(kTextureTransform);
        // Not an object: nothing to read (and tinygltf's Value::Get asserts on it).
        if (it != extensions->end() && !it->second.IsObject()) it = extensions->end();
        const glm::mat3x2 t = it == extensions->end() ? glm::mat3x2(1.0f) : transformOf(it->second);
        if (it != extensions->end()) {
            r.present = true;
            const tinygltf::Value& texCoord = it->second.Get("texCoord");
            if (texCoord.IsNumber() && texCoord.GetNumberAsInt() != 0 && r.problem.empty())
                r.problem = std::string("on ") + name + " selects TEXCOORD_" +
                            std::to_string(texCoord.GetNumberAsInt()) +
                            ", which is ignored (only TEXCOORD_0 is read)";
        }
        if (!first) {
            first = name;
            r.matrix = t;
        } else if (t != r.matrix && r.problem.find("differs") == std::string::npos) {
            // One uv set per vertex: the transform is baked into it, so it can only be one.
            r.problem = std::string("differs between ") + first + " and " + name + "; only " +
                        first + "'s is applied, to every texture of the material";
        }
    }
    return r;
}

} // namespace tp::gltf
