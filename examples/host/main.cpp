// A host renderer for mxc's shaders that knows nothing of mxc: it reads the interface JSON that
// `mxc compile -o OUT.spv --tables DIR` writes (docs/shader-interface.md), the two SPIR-V stages
// and the albedo tables file, and renders the material on a sphere under one directional light
// with Vulkan, frames accumulated as the interface says. It links Vulkan, nlohmann-json and
// OpenImageIO only: every block offset, binding, format and default comes from the JSON.
//
//   mxc compile material.mtlx -o out/m.spv --tables out
//   mxc_example_host out/m.json out/m.exr [--size N] [--frames N]
//
// The scene is the one `mxc render --env none` draws by default: a unit sphere seen from
// (0, 0, 3.4) with a 45 degree field of view, lit by a directional light towards (-1, 1.2, 1.5)
// of irradiance 2. tests/examples/HostTest.cpp compares the two images.

#include <vulkan/vulkan.h>

#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

[[noreturn]] void fail(const std::string& message) { throw std::runtime_error(message); }

void check(VkResult result, const char* what) {
  if (result != VK_SUCCESS) fail(std::string(what) + " failed (VkResult " + std::to_string(int(result)) + ")");
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail("cannot read " + path.string());
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// ---- a little linear algebra (column-major 4x4, as GLSL's mat4) ----
struct Mat4 {
  float m[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  float& at(int column, int row) { return m[column * 4 + row]; }
  float at(int column, int row) const { return m[column * 4 + row]; }
};
Mat4 operator*(const Mat4& a, const Mat4& b) {
  Mat4 out;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      float sum = 0.0f;
      for (int k = 0; k < 4; ++k) sum += a.at(k, r) * b.at(c, k);
      out.at(c, r) = sum;
    }
  return out;
}

/// Right-handed view looking from `eye` at the origin, y up.
Mat4 lookAtOrigin(const float eye[3]) {
  // Forward f = -eye / |eye| (|eye| > 0: the camera is not at the origin); up (0, 1, 0) is not along it.
  const float len = std::sqrt(eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]);
  const float f[3] = {-eye[0] / len, -eye[1] / len, -eye[2] / len};
  float s[3] = {f[1] * 0 - f[2] * 1, f[2] * 0 - f[0] * 0, f[0] * 1 - f[1] * 0};  // f x up
  const float sl = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
  for (float& x : s) x /= sl;
  const float u[3] = {s[1] * f[2] - s[2] * f[1], s[2] * f[0] - s[0] * f[2], s[0] * f[1] - s[1] * f[0]};
  Mat4 v;
  for (int i = 0; i < 3; ++i) {
    v.at(i, 0) = s[i];
    v.at(i, 1) = u[i];
    v.at(i, 2) = -f[i];
  }
  v.at(3, 0) = -(s[0] * eye[0] + s[1] * eye[1] + s[2] * eye[2]);
  v.at(3, 1) = -(u[0] * eye[0] + u[1] * eye[1] + u[2] * eye[2]);
  v.at(3, 2) = f[0] * eye[0] + f[1] * eye[1] + f[2] * eye[2];
  return v;
}

/// Vulkan's clip space: depth 0..1, y down.
Mat4 perspective(float fovY, float aspect, float nearZ, float farZ) {
  const float t = std::tan(fovY / 2.0f);
  Mat4 p;
  std::memset(p.m, 0, sizeof(p.m));
  p.at(0, 0) = 1.0f / (aspect * t);
  p.at(1, 1) = -1.0f / t;
  p.at(2, 2) = farZ / (nearZ - farZ);
  p.at(2, 3) = -1.0f;
  p.at(3, 2) = -(farZ * nearZ) / (farZ - nearZ);
  return p;
}

float radicalInverse(uint32_t index, uint32_t base) {
  float f = 1.0f, r = 0.0f;
  for (; index > 0; index /= base) {
    f /= float(base);
    r += f * float(index % base);
  }
  return r;
}

// ---- Vulkan objects ----
struct Gpu {
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  uint32_t family = 0;
  VkCommandPool pool = VK_NULL_HANDLE;

  uint32_t memoryType(uint32_t bits, VkMemoryPropertyFlags flags) const {
    VkPhysicalDeviceMemoryProperties props;
    vkGetPhysicalDeviceMemoryProperties(physical, &props);
    for (uint32_t i = 0; i < props.memoryTypeCount; ++i) {
      if ((bits & (1u << i)) && (props.memoryTypes[i].propertyFlags & flags) == flags) return i;
    }
    fail("no suitable memory type");
  }

  void submit(const std::function<void(VkCommandBuffer)>& record) const {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer cmd;
    check(vkAllocateCommandBuffers(device, &alloc, &cmd), "vkAllocateCommandBuffers");
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(cmd, &begin);
    record(cmd);
    vkEndCommandBuffer(cmd);
    VkSubmitInfo submitInfo{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submitInfo.commandBufferCount = 1;
    submitInfo.pCommandBuffers = &cmd;
    check(vkQueueSubmit(queue, 1, &submitInfo, VK_NULL_HANDLE), "vkQueueSubmit");
    check(vkQueueWaitIdle(queue), "vkQueueWaitIdle");
    vkFreeCommandBuffers(device, pool, 1, &cmd);
  }
};

Gpu createGpu() {
  Gpu gpu;
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "mxc_example_host";
  app.apiVersion = VK_API_VERSION_1_1;  // the interface's shaders are SPIR-V 1.3 for Vulkan 1.1
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  check(vkCreateInstance(&info, nullptr, &gpu.instance), "vkCreateInstance");
  uint32_t count = 0;
  vkEnumeratePhysicalDevices(gpu.instance, &count, nullptr);
  if (count == 0) fail("no Vulkan device");
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(gpu.instance, &count, devices.data());
  gpu.physical = devices[0];
  uint32_t families = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(gpu.physical, &families, nullptr);
  std::vector<VkQueueFamilyProperties> props(families);
  vkGetPhysicalDeviceQueueFamilyProperties(gpu.physical, &families, props.data());
  bool found = false;
  for (uint32_t i = 0; i < families && !found; ++i) {
    if (props[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) gpu.family = i, found = true;
  }
  if (!found) fail("no graphics queue");
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queue.queueFamilyIndex = gpu.family;
  queue.queueCount = 1;
  queue.pQueuePriorities = &priority;
  VkDeviceCreateInfo device{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  device.queueCreateInfoCount = 1;
  device.pQueueCreateInfos = &queue;
  check(vkCreateDevice(gpu.physical, &device, nullptr, &gpu.device), "vkCreateDevice");
  vkGetDeviceQueue(gpu.device, gpu.family, 0, &gpu.queue);
  VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool.queueFamilyIndex = gpu.family;
  check(vkCreateCommandPool(gpu.device, &pool, nullptr, &gpu.pool), "vkCreateCommandPool");
  return gpu;
}

struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;
  VkDeviceSize size = 0;
};

/// A host-visible, host-coherent buffer, mapped: simple, and fast enough on a software device.
Buffer createBuffer(const Gpu& gpu, VkDeviceSize size, VkBufferUsageFlags usage) {
  Buffer b;
  b.size = std::max<VkDeviceSize>(size, 16);
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = b.size;
  info.usage = usage;
  check(vkCreateBuffer(gpu.device, &info, nullptr, &b.buffer), "vkCreateBuffer");
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(gpu.device, b.buffer, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex =
      gpu.memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  check(vkAllocateMemory(gpu.device, &alloc, nullptr, &b.memory), "vkAllocateMemory");
  vkBindBufferMemory(gpu.device, b.buffer, b.memory, 0);
  vkMapMemory(gpu.device, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped);
  std::memset(b.mapped, 0, b.size);
  return b;
}

struct Image {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
};

Image createImage(const Gpu& gpu, uint32_t width, uint32_t height, uint32_t levels, VkFormat format,
                  VkImageUsageFlags usage, VkImageAspectFlags aspect) {
  Image img;
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {width, height, 1};
  info.mipLevels = levels;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  check(vkCreateImage(gpu.device, &info, nullptr, &img.image), "vkCreateImage");
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(gpu.device, img.image, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = gpu.memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  check(vkAllocateMemory(gpu.device, &alloc, nullptr, &img.memory), "vkAllocateMemory");
  vkBindImageMemory(gpu.device, img.image, img.memory, 0);
  VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  view.image = img.image;
  view.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view.format = format;
  view.subresourceRange = {aspect, 0, levels, 0, 1};
  check(vkCreateImageView(gpu.device, &view, nullptr, &img.view), "vkCreateImageView");
  return img;
}

void barrier(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to, uint32_t levels,
             VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT) {
  VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = {aspect, 0, levels, 0, 1};
  b.srcAccessMask = VK_ACCESS_MEMORY_WRITE_BIT;
  b.dstAccessMask = VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT;
  vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, 0, 0, nullptr, 0,
                       nullptr, 1, &b);
}

/// RGBA float texels, level 0 first, each level half the one above (rounded down, at least 1).
struct Texels {
  uint32_t width = 1, height = 1;
  std::vector<std::vector<float>> levels;
};

/// The mip chain by 2x2 box filtering (the interface asks for "full chain").
void buildMips(Texels& t) {
  uint32_t w = t.width, h = t.height;
  while (w > 1 || h > 1) {
    const uint32_t nw = std::max(w / 2, 1u), nh = std::max(h / 2, 1u);
    const std::vector<float>& src = t.levels.back();
    std::vector<float> dst(size_t(nw) * nh * 4);
    for (uint32_t y = 0; y < nh; ++y)
      for (uint32_t x = 0; x < nw; ++x)
        for (uint32_t c = 0; c < 4; ++c) {
          float sum = 0.0f;
          for (uint32_t dy = 0; dy < 2; ++dy)
            for (uint32_t dx = 0; dx < 2; ++dx) {
              const uint32_t sx = std::min(2 * x + dx, w - 1), sy = std::min(2 * y + dy, h - 1);
              sum += src[(size_t(sy) * w + sx) * 4 + c];
            }
          dst[(size_t(y) * nw + x) * 4 + c] = 0.25f * sum;
        }
    t.levels.push_back(std::move(dst));
    w = nw, h = nh;
  }
}

Image uploadTexture(const Gpu& gpu, const Texels& t) {
  const uint32_t levels = uint32_t(t.levels.size());
  Image img = createImage(gpu, t.width, t.height, levels, VK_FORMAT_R32G32B32A32_SFLOAT,
                          VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
  size_t bytes = 0;
  for (const auto& level : t.levels) bytes += level.size() * sizeof(float);
  Buffer staging = createBuffer(gpu, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  std::vector<VkBufferImageCopy> copies;
  size_t offset = 0;
  uint32_t w = t.width, h = t.height;
  for (uint32_t l = 0; l < levels; ++l) {
    std::memcpy(static_cast<char*>(staging.mapped) + offset, t.levels[l].data(), t.levels[l].size() * sizeof(float));
    VkBufferImageCopy copy{};
    copy.bufferOffset = offset;
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, l, 0, 1};
    copy.imageExtent = {w, h, 1};
    copies.push_back(copy);
    offset += t.levels[l].size() * sizeof(float);
    w = std::max(w / 2, 1u), h = std::max(h / 2, 1u);
  }
  gpu.submit([&](VkCommandBuffer cmd) {
    barrier(cmd, img.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, levels);
    vkCmdCopyBufferToImage(cmd, staging.buffer, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, uint32_t(copies.size()),
                           copies.data());
    barrier(cmd, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, levels);
  });
  return img;
}

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

/// A texture file as RGBA floats, decoded from sRGB when the interface says so; nullopt-like
/// (empty levels) when it cannot be read.
Texels readTexture(const fs::path& file, bool decodeSrgb) {
  Texels t;
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) return t;
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<float> pixels(size_t(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data())) return t;
  t.width = uint32_t(spec.width), t.height = uint32_t(spec.height);
  std::vector<float> rgba(size_t(t.width) * t.height * 4);
  for (size_t p = 0; p < size_t(t.width) * t.height; ++p) {
    const float* s = &pixels[p * spec.nchannels];
    // Grey fills RGB; a missing alpha is 1.
    const float r = s[0], g = spec.nchannels > 1 ? s[1] : s[0], b = spec.nchannels > 2 ? s[2] : s[0];
    const float a = spec.nchannels > 3 ? s[3] : 1.0f;
    const bool eight = spec.format.basetype == OIIO::TypeDesc::UINT8;
    rgba[p * 4 + 0] = decodeSrgb && eight ? srgbToLinear(r) : r;
    rgba[p * 4 + 1] = decodeSrgb && eight ? srgbToLinear(g) : g;
    rgba[p * 4 + 2] = decodeSrgb && eight ? srgbToLinear(b) : b;
    rgba[p * 4 + 3] = a;
  }
  t.levels.push_back(std::move(rgba));
  buildMips(t);
  return t;
}

/// The albedo tables file (docs/shader-interface.md): "MXCTAB01", uint32 width, height,
/// channels, uint64 hash, then RGBA float32 texels.
Texels readTables(const fs::path& file) {
  const std::string bytes = readFile(file);
  if (bytes.size() < 28 || bytes.compare(0, 8, "MXCTAB01") != 0) fail(file.string() + ": not an albedo tables file");
  uint32_t header[3];
  std::memcpy(header, bytes.data() + 8, sizeof(header));
  const size_t texels = size_t(header[0]) * header[1];
  if (header[2] != 4 || bytes.size() != 28 + texels * 16) fail(file.string() + ": truncated or of another layout");
  Texels t;
  t.width = header[0], t.height = header[1];
  t.levels.emplace_back(texels * 4);
  std::memcpy(t.levels[0].data(), bytes.data() + 28, texels * 16);
  return t;
}

/// Writes a value given as JSON numbers at `offset`, by its GLSL type, std140 (matrices as
/// 16-byte columns of the row-by-row values).
void writeValue(char* block, uint32_t offset, const std::string& type, const json& value) {
  std::vector<float> v;
  for (const json& x : value) v.push_back(x.get<float>());
  if (type == "int" || type == "bool" || type == "uint" || type == "ivec2" || type == "ivec3" || type == "ivec4") {
    for (size_t i = 0; i < v.size(); ++i) {
      const int32_t n = int32_t(v[i]);
      std::memcpy(block + offset + 4 * i, &n, 4);
    }
  } else if (type == "mat3" || type == "mat4") {
    const size_t n = type == "mat3" ? 3 : 4;
    for (size_t row = 0; row < n; ++row)
      for (size_t col = 0; col < n && row * n + col < v.size(); ++col)
        std::memcpy(block + offset + col * 16 + row * 4, &v[row * n + col], 4);
  } else {
    std::memcpy(block + offset, v.data(), v.size() * sizeof(float));
  }
}

VkShaderModule shaderModule(const Gpu& gpu, const fs::path& file) {
  const std::string code = readFile(file);
  VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  info.codeSize = code.size();
  info.pCode = reinterpret_cast<const uint32_t*>(code.data());
  VkShaderModule module;
  check(vkCreateShaderModule(gpu.device, &info, nullptr, &module), "vkCreateShaderModule");
  return module;
}

struct Vertex {
  float position[3], normal[3], tangent[4], uv[2];
};

/// A unit sphere, u around +y from +z, v from the south pole up; tangents along increasing u.
void sphere(std::vector<Vertex>& vertices, std::vector<uint32_t>& indices, uint32_t segments, uint32_t rings) {
  const float pi = 3.14159265358979f;
  for (uint32_t r = 0; r <= rings; ++r) {
    const float v = float(r) / float(rings), theta = pi * (1.0f - v);
    for (uint32_t s = 0; s <= segments; ++s) {
      const float u = float(s) / float(segments), phi = 2.0f * pi * u;
      const float p[3] = {std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi)};
      vertices.push_back({{p[0], p[1], p[2]}, {p[0], p[1], p[2]}, {std::cos(phi), 0.0f, -std::sin(phi), 1.0f}, {u, v}});
    }
  }
  for (uint32_t r = 0; r < rings; ++r)
    for (uint32_t s = 0; s < segments; ++s) {
      const uint32_t a = r * (segments + 1) + s, b = a + 1, c = a + segments + 1, d = c + 1;
      indices.insert(indices.end(), {a, b, d, a, d, c});
    }
}

struct Options {
  fs::path interface, output;
  uint32_t size = 256;
  uint32_t frames = 16;
};

int run(const Options& options) {
  const json interface = json::parse(readFile(options.interface));
  if (interface.value("schema", "") != "mxc-shader-interface-1") fail("not an mxc shader interface (schema)");
  if (interface.value("kind", "") != "raster" || interface.value("target", "spirv") != "spirv") {
    fail("this host renders the raster shader in SPIR-V: compile with -o OUT.spv");
  }
  const fs::path folder = options.interface.parent_path();
  const fs::path documentFolder = interface.value("documentFolder", "");
  Gpu gpu = createGpu();

  // Descriptor set layouts, one per set, from the descriptors.
  std::map<uint32_t, std::vector<VkDescriptorSetLayoutBinding>> layouts;
  std::map<std::string, VkDescriptorType> typeOf{{"combined_image_sampler", VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER},
                                                 {"uniform_buffer", VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER},
                                                 {"storage_buffer", VK_DESCRIPTOR_TYPE_STORAGE_BUFFER}};
  for (const json& d : interface["descriptors"]) {
    VkDescriptorSetLayoutBinding b{};
    b.binding = d["binding"];
    b.descriptorType = typeOf.at(d["type"]);
    b.descriptorCount = 1;
    b.stageFlags = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    layouts[d["set"]].push_back(b);
  }
  const uint32_t setCount = layouts.empty() ? 0 : layouts.rbegin()->first + 1;
  std::vector<VkDescriptorSetLayout> setLayouts(setCount);
  for (uint32_t s = 0; s < setCount; ++s) {
    VkDescriptorSetLayoutCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    info.bindingCount = uint32_t(layouts[s].size());
    info.pBindings = layouts[s].data();
    check(vkCreateDescriptorSetLayout(gpu.device, &info, nullptr, &setLayouts[s]), "vkCreateDescriptorSetLayout");
  }
  VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 64},
                                  {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 16},
                                  {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 16}};
  VkDescriptorPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  poolInfo.maxSets = std::max(setCount, 1u);
  poolInfo.poolSizeCount = 3;
  poolInfo.pPoolSizes = sizes;
  VkDescriptorPool pool;
  check(vkCreateDescriptorPool(gpu.device, &poolInfo, nullptr, &pool), "vkCreateDescriptorPool");
  std::vector<VkDescriptorSet> sets(setCount);
  VkDescriptorSetAllocateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  setInfo.descriptorPool = pool;
  setInfo.descriptorSetCount = setCount;
  setInfo.pSetLayouts = setLayouts.data();
  check(vkAllocateDescriptorSets(gpu.device, &setInfo, sets.data()), "vkAllocateDescriptorSets");

  // Each descriptor's resource, as the interface describes it.
  VkSamplerCreateInfo samplerInfo{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
  samplerInfo.magFilter = samplerInfo.minFilter = VK_FILTER_LINEAR;
  samplerInfo.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
  samplerInfo.addressModeU = samplerInfo.addressModeV = samplerInfo.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
  samplerInfo.maxLod = VK_LOD_CLAMP_NONE;
  VkSampler sampler;
  check(vkCreateSampler(gpu.device, &samplerInfo, nullptr, &sampler), "vkCreateSampler");
  Buffer view{};
  json viewMembers;
  std::map<std::string, uint32_t> missingTextures;  // each missing_textures mask member's bits
  Buffer parameters{};
  for (const json& d : interface["descriptors"]) {
    const std::string name = d["name"], type = d["type"];
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = sets[d["set"].get<uint32_t>()];
    write.dstBinding = d["binding"];
    write.descriptorCount = 1;
    write.descriptorType = typeOf.at(type);
    VkDescriptorImageInfo imageInfo{sampler, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorBufferInfo bufferInfo{};
    if (type == "combined_image_sampler") {
      Texels texels;
      if (name == "mxc_tables") {
        const std::string file = interface["tables"][0].value("file", "");
        if (file.empty()) fail("the interface names no tables file: compile with --tables DIR");
        texels = readTables(folder / file);
      } else if (d.contains("file")) {
        texels = readTexture(documentFolder / d["file"].get<std::string>(), d.value("decode", "none") == "srgb");
        if (texels.levels.empty()) {
          std::fprintf(stderr, "warning: cannot read %s: the material uses the image node's default\n",
                       d["file"].get<std::string>().c_str());
          missingTextures[d.value("missingMember", std::string("missing_textures"))] |= 1u << (d.value("missingBit", 0u) % 32);
        }
      }
      if (texels.levels.empty()) texels.levels.push_back({0, 0, 0, 0});  // the environment (none here), or a missing file
      imageInfo.imageView = uploadTexture(gpu, texels).view;
      write.pImageInfo = &imageInfo;
    } else {
      const bool storage = type == "storage_buffer";
      Buffer b = createBuffer(gpu, d.value("size", 256u),
                              storage ? VK_BUFFER_USAGE_STORAGE_BUFFER_BIT : VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT);
      if (name == "MxcView") view = b, viewMembers = d["members"];
      if (name == "MxcParameters") {
        parameters = b;
        for (const json& m : d["members"]) {
          if (m.contains("default")) writeValue(static_cast<char*>(b.mapped), m["offset"], m["type"], m["default"]);
        }
      }
      bufferInfo = {b.buffer, 0, VK_WHOLE_SIZE};
      write.pBufferInfo = &bufferInfo;
    }
    vkUpdateDescriptorSets(gpu.device, 1, &write, 0, nullptr);
  }
  if (!view.buffer) fail("the interface has no MxcView block");
  auto viewOffset = [&](const std::string& name) -> uint32_t {
    for (const json& m : viewMembers) {
      if (m["name"] == name) return m["offset"];
    }
    fail("MxcView has no member " + name);
  };
  if (parameters.buffer) {
    for (const json& d : interface["descriptors"]) {
      if (d["name"] != "MxcParameters") continue;
      for (const json& m : d["members"]) {
        auto bits = missingTextures.find(m["name"].get<std::string>());
        if (bits != missingTextures.end()) std::memcpy(static_cast<char*>(parameters.mapped) + m["offset"].get<uint32_t>(), &bits->second, 4);
      }
    }
  }

  // The pipeline: the vertex inputs as the interface lists them, one interleaved buffer.
  const uint32_t size = options.size;
  const VkFormat colorFormat = VK_FORMAT_R32G32B32A32_SFLOAT, depthFormat = VK_FORMAT_D32_SFLOAT;
  VkAttachmentDescription attachments[2]{};
  attachments[0].format = colorFormat;
  attachments[0].samples = VK_SAMPLE_COUNT_1_BIT;
  attachments[0].loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;  // frames accumulate (additive blending)
  attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  attachments[0].initialLayout = attachments[0].finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
  attachments[1].format = depthFormat;
  attachments[1].samples = VK_SAMPLE_COUNT_1_BIT;
  attachments[1].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;  // each frame its own depth
  attachments[1].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  attachments[1].initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  attachments[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
  VkAttachmentReference colorRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &colorRef;
  subpass.pDepthStencilAttachment = &depthRef;
  VkRenderPassCreateInfo passInfo{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  passInfo.attachmentCount = 2;
  passInfo.pAttachments = attachments;
  passInfo.subpassCount = 1;
  passInfo.pSubpasses = &subpass;
  VkRenderPass renderPass;
  check(vkCreateRenderPass(gpu.device, &passInfo, nullptr, &renderPass), "vkCreateRenderPass");
  Image color = createImage(gpu, size, size, 1, colorFormat,
                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                            VK_IMAGE_ASPECT_COLOR_BIT);
  Image depth = createImage(gpu, size, size, 1, depthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                            VK_IMAGE_ASPECT_DEPTH_BIT);
  VkImageView views[2] = {color.view, depth.view};
  VkFramebufferCreateInfo fbInfo{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fbInfo.renderPass = renderPass;
  fbInfo.attachmentCount = 2;
  fbInfo.pAttachments = views;
  fbInfo.width = fbInfo.height = size;
  fbInfo.layers = 1;
  VkFramebuffer framebuffer;
  check(vkCreateFramebuffer(gpu.device, &fbInfo, nullptr, &framebuffer), "vkCreateFramebuffer");

  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = setCount;
  layoutInfo.pSetLayouts = setLayouts.data();
  VkPipelineLayout pipelineLayout;
  check(vkCreatePipelineLayout(gpu.device, &layoutInfo, nullptr, &pipelineLayout), "vkCreatePipelineLayout");
  const json& stages = interface["stages"];
  VkPipelineShaderStageCreateInfo shaderStages[2]{};
  const std::string vertexEntry = stages["vertex"]["entryPoint"], fragmentEntry = stages["fragment"]["entryPoint"];
  shaderStages[0] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_VERTEX_BIT,
                     shaderModule(gpu, folder / stages["vertex"]["file"].get<std::string>()), vertexEntry.c_str(), nullptr};
  shaderStages[1] = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_FRAGMENT_BIT,
                     shaderModule(gpu, folder / stages["fragment"]["file"].get<std::string>()), fragmentEntry.c_str(), nullptr};
  // The vertex attributes by name; the formats are the interface's.
  const std::map<std::string, uint32_t> attributeOffset{{"inPosition", offsetof(Vertex, position)},
                                                         {"inNormal", offsetof(Vertex, normal)},
                                                         {"inTangent", offsetof(Vertex, tangent)},
                                                         {"inUv", offsetof(Vertex, uv)}};
  const std::map<std::string, VkFormat> formats{{"R32G32B32_SFLOAT", VK_FORMAT_R32G32B32_SFLOAT},
                                                {"R32G32B32A32_SFLOAT", VK_FORMAT_R32G32B32A32_SFLOAT},
                                                {"R32G32_SFLOAT", VK_FORMAT_R32G32_SFLOAT}};
  std::vector<VkVertexInputAttributeDescription> attributes;
  for (const json& input : interface["vertexInputs"]) {
    attributes.push_back({input["location"], 0, formats.at(input["format"]), attributeOffset.at(input["name"])});
  }
  VkVertexInputBindingDescription vertexBinding{0, sizeof(Vertex), VK_VERTEX_INPUT_RATE_VERTEX};
  VkPipelineVertexInputStateCreateInfo vertexInput{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
  vertexInput.vertexBindingDescriptionCount = 1;
  vertexInput.pVertexBindingDescriptions = &vertexBinding;
  vertexInput.vertexAttributeDescriptionCount = uint32_t(attributes.size());
  vertexInput.pVertexAttributeDescriptions = attributes.data();
  VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkViewport viewport{0, 0, float(size), float(size), 0, 1};
  VkRect2D scissor{{0, 0}, {size, size}};
  VkPipelineViewportStateCreateInfo viewportState{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
  viewportState.viewportCount = viewportState.scissorCount = 1;
  viewportState.pViewports = &viewport;
  viewportState.pScissors = &scissor;
  VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
  // Additive blending adds every fragment that passes the depth test, also one drawn before a
  // nearer one: the sphere's far side is culled. Its triangles turn counter-clockwise seen from
  // outside, in Vulkan's framebuffer too (the projection flips y, and so does the framebuffer's
  // y axis against clip space's). The shader reads gl_FrontFacing: front must be the outside.
  raster.cullMode = VK_CULL_MODE_BACK_BIT;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;
  VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  VkPipelineDepthStencilStateCreateInfo depthState{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
  depthState.depthTestEnable = depthState.depthWriteEnable = VK_TRUE;
  depthState.depthCompareOp = VK_COMPARE_OP_LESS;
  // Frames add up (ONE, ONE), as "fragmentOutputs" says; the image is the sum over the frames.
  VkPipelineColorBlendAttachmentState blend{};
  blend.blendEnable = VK_TRUE;
  blend.srcColorBlendFactor = blend.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
  blend.srcAlphaBlendFactor = blend.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
  blend.colorBlendOp = blend.alphaBlendOp = VK_BLEND_OP_ADD;
  blend.colorWriteMask = 0xf;
  VkPipelineColorBlendStateCreateInfo blendState{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
  blendState.attachmentCount = 1;
  blendState.pAttachments = &blend;
  VkGraphicsPipelineCreateInfo pipelineInfo{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
  pipelineInfo.stageCount = 2;
  pipelineInfo.pStages = shaderStages;
  pipelineInfo.pVertexInputState = &vertexInput;
  pipelineInfo.pInputAssemblyState = &assembly;
  pipelineInfo.pViewportState = &viewportState;
  pipelineInfo.pRasterizationState = &raster;
  pipelineInfo.pMultisampleState = &multisample;
  pipelineInfo.pDepthStencilState = &depthState;
  pipelineInfo.pColorBlendState = &blendState;
  pipelineInfo.layout = pipelineLayout;
  pipelineInfo.renderPass = renderPass;
  VkPipeline pipeline;
  check(vkCreateGraphicsPipelines(gpu.device, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr, &pipeline),
        "vkCreateGraphicsPipelines");

  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;
  sphere(vertices, indices, 128, 64);
  Buffer vertexBuffer = createBuffer(gpu, vertices.size() * sizeof(Vertex), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
  std::memcpy(vertexBuffer.mapped, vertices.data(), vertices.size() * sizeof(Vertex));
  Buffer indexBuffer = createBuffer(gpu, indices.size() * 4, VK_BUFFER_USAGE_INDEX_BUFFER_BIT);
  std::memcpy(indexBuffer.mapped, indices.data(), indices.size() * 4);

  // The scene: the camera mxc render frames a unit sphere with, one directional light.
  const float eye[3] = {0.0f, 0.0f, 3.4f};
  const float nearZ = 0.5f * (3.4f - 1.0f), farZ = 1.5f * (3.4f + 1.0f);
  const Mat4 worldToClip = perspective(45.0f * 3.14159265f / 180.0f, 1.0f, nearZ, farZ) * lookAtOrigin(eye);
  char* block = static_cast<char*>(view.mapped);
  const Mat4 identity;
  std::memcpy(block + viewOffset("objectToWorld"), identity.m, 64);
  std::memcpy(block + viewOffset("normalToWorld"), identity.m, 64);
  std::memcpy(block + viewOffset("worldToClip"), worldToClip.m, 64);
  const float eye4[4] = {eye[0], eye[1], eye[2], 1.0f};
  std::memcpy(block + viewOffset("eye"), eye4, 16);
  const float l[3] = {-1.0f, 1.2f, 1.5f};
  const float ll = std::sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
  const float lightVector[4] = {l[0] / ll, l[1] / ll, l[2] / ll, 0.0f};  // w = 0: directional
  const float lightRadiance[4] = {2.0f, 2.0f, 2.0f, 0.0f};
  std::memcpy(block + viewOffset("lightVector"), lightVector, 16);
  std::memcpy(block + viewOffset("lightRadiance"), lightRadiance, 16);
  const float environment[4] = {1.0f, 1.0f, 0.0f, 0.0f};  // intensity, emission scale, rotation
  std::memcpy(block + viewOffset("environment"), environment, 16);

  gpu.submit([&](VkCommandBuffer cmd) {
    barrier(cmd, color.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1);
    VkClearColorValue zero{};
    VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, color.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &range);
    barrier(cmd, color.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, 1);
  });
  const uint32_t frames = std::max(options.frames, 1u);
  for (uint32_t frame = 0; frame < frames; ++frame) {
    // Sub-pixel jitter in normalised device units (the vertex stage adds it); frame 0 at pixel centres.
    const float jx = frame == 0 ? 0.0f : radicalInverse(frame, 2) - 0.5f;
    const float jy = frame == 0 ? 0.0f : radicalInverse(frame, 3) - 0.5f;
    const float jitter[4] = {2.0f * jx / float(size), 2.0f * jy / float(size), 1.0f / std::sqrt(float(frames)), 0.0f};
    std::memcpy(block + viewOffset("jitter"), jitter, 16);
    const int32_t counts[4] = {1, 0, int32_t(frame), 1};  // lights, environment none, frame, samples
    std::memcpy(block + viewOffset("counts"), counts, 16);
    gpu.submit([&](VkCommandBuffer cmd) {
      VkClearValue clears[2]{};
      clears[1].depthStencil = {1.0f, 0};
      VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
      begin.renderPass = renderPass;
      begin.framebuffer = framebuffer;
      begin.renderArea = {{0, 0}, {size, size}};
      begin.clearValueCount = 2;
      begin.pClearValues = clears;
      vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
      vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
      vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelineLayout, 0, setCount, sets.data(), 0, nullptr);
      VkDeviceSize zero = 0;
      vkCmdBindVertexBuffers(cmd, 0, 1, &vertexBuffer.buffer, &zero);
      vkCmdBindIndexBuffer(cmd, indexBuffer.buffer, 0, VK_INDEX_TYPE_UINT32);
      vkCmdDrawIndexed(cmd, uint32_t(indices.size()), 1, 0, 0, 0);
      vkCmdEndRenderPass(cmd);
    });
  }

  // Read the sum back and average it.
  Buffer readback = createBuffer(gpu, VkDeviceSize(size) * size * 16, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  gpu.submit([&](VkCommandBuffer cmd) {
    barrier(cmd, color.image, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, 1);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {size, size, 1};
    vkCmdCopyImageToBuffer(cmd, color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1, &copy);
  });
  std::vector<float> pixels(size_t(size) * size * 4);
  std::memcpy(pixels.data(), readback.mapped, pixels.size() * sizeof(float));
  for (float& p : pixels) p /= float(frames);  // frames >= 1
  auto out = OIIO::ImageOutput::create(options.output.string());
  if (!out) fail("cannot write " + options.output.string() + ": " + OIIO::geterror());
  const OIIO::ImageSpec spec(static_cast<int>(size), static_cast<int>(size), 4, OIIO::TypeDesc::FLOAT);
  if (!out->open(options.output.string(), spec) || !out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) ||
      !out->close()) {
    fail("cannot write " + options.output.string() + ": " + out->geterror());
  }
  std::printf("%s: %ux%u, %u frames, material %s\n", options.output.string().c_str(), size, size, frames,
              interface.value("material", "").c_str());
  vkDeviceWaitIdle(gpu.device);
  return 0;  // the process ends: the driver releases every object
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if ((a == "--size" || a == "--frames") && i + 1 < argc) {
      const long n = std::strtol(argv[++i], nullptr, 10);
      if (n < 1 || n > 4096) {
        std::fprintf(stderr, "error: %s must be between 1 and 4096\n", a.c_str());
        return 2;
      }
      (a == "--size" ? options.size : options.frames) = uint32_t(n);
    } else {
      positional.push_back(a);
    }
  }
  if (positional.size() != 2) {
    std::fprintf(stderr, "usage: mxc_example_host SHADER.json OUT.exr [--size N] [--frames N]\n");
    return 2;
  }
  options.interface = positional[0];
  options.output = positional[1];
  try {
    return run(options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
