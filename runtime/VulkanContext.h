#pragma once
/// \file
/// The Vulkan device the harness runs on: instance, device selection (Mesa lavapipe by
/// default), one queue for graphics and compute, validation-layer messages, and the few
/// resource helpers the renderer and the evaluator share.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

namespace mxc::rt {

/// A Vulkan call failed, or no usable device was found.
class VulkanError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A Vulkan call that ran out of device or host memory (VK_ERROR_OUT_OF_DEVICE_MEMORY,
/// VK_ERROR_OUT_OF_HOST_MEMORY): a std::bad_alloc, so that it ends a command as running out of
/// memory does (exit 4, cli/Main.cpp), with what ran out.
class VulkanOutOfMemory : public std::bad_alloc {
 public:
  explicit VulkanOutOfMemory(std::string what) : what_(std::move(what)) {}
  const char* what() const noexcept override { return what_.c_str(); }

 private:
  std::string what_;
};

/// Throws VulkanError naming the call when `result` is not VK_SUCCESS.
void check(VkResult result, const char* what);

struct DeviceOptions {
  /// A device by index or by a part of its name ("llvmpipe", "NVIDIA"); empty picks lavapipe
  /// when present, else the first device.
  std::string device;
  /// Enable VK_LAYER_KHRONOS_validation and collect its messages (tests fail on any).
  bool validation = false;
};

/// A host-visible, coherent buffer.
struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkDeviceSize size = 0;
  void* mapped = nullptr;
};

/// A 2D image with its view (and, for sampled images, a sampler).
struct Image {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
  VkSampler sampler = VK_NULL_HANDLE;
  VkFormat format = VK_FORMAT_UNDEFINED;
  uint32_t width = 0;
  uint32_t height = 0;
  uint32_t mipLevels = 1;
};

class VulkanContext {
 public:
  explicit VulkanContext(const DeviceOptions& options = {});
  ~VulkanContext();
  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  VkDevice device() const { return device_; }
  VkPhysicalDevice physicalDevice() const { return physical_; }
  VkQueue queue() const { return queue_; }
  uint32_t queueFamily() const { return queueFamily_; }
  const std::string& deviceName() const { return deviceName_; }
  /// The largest width or height of a 2D image the device takes (VkPhysicalDeviceLimits).
  uint32_t maxImageDimension2D() const { return maxImageDimension2D_; }
  /// The device's limits (VkPhysicalDeviceLimits), for checks such as runtime/DescriptorLimits.h.
  const VkPhysicalDeviceLimits& limits() const { return limits_; }
  /// Each device as "INDEX: NAME (TYPE), Vulkan X.Y.Z, DRIVER DRIVER-INFO" (the driver from
  /// VK_KHR_driver_properties where the device has it: "llvmpipe Mesa 22.3.6 (LLVM 15.0.6)"),
  /// or why Vulkan cannot be used.
  static std::vector<std::string> describeDevices();

  /// Validation messages received so far (errors and warnings), and a way to clear them.
  const std::vector<std::string>& validationMessages() const { return *messages_; }
  void clearValidationMessages() { messages_->clear(); }

  Buffer createBuffer(VkDeviceSize size, VkBufferUsageFlags usage);
  void destroy(Buffer& buffer);
  /// Throws VulkanError for a size the device does not take (callers downsample first).
  /// A sampled image's sampler clamps unless told otherwise: mxc's shaders address in the
  /// shader (MaterialX address modes); other generators' shaders rely on the sampler.
  Image createImage(uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage,
                    VkSamplerAddressMode addressU = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                    VkSamplerAddressMode addressV = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE);
  /// A sampled texture of a material: with a full mip chain (down to 1x1, filtered trilinearly)
  /// when the device can blit `format` with linear filtering, else one level. upload() fills
  /// level 0 and makes the others from it.
  Image createTexture(uint32_t width, uint32_t height, VkFormat format);
  void destroy(Image& image);
  /// Fills an RGBA32F image created with TRANSFER_DST and SAMPLED usage from `rgba`
  /// (width * height * 4 floats, top row first) and leaves it ready for sampling.
  void upload(Image& image, const float* rgba);
  /// Any format: `texels` holds width x height texels of `bytesPerTexel` bytes each. An image
  /// with mip levels gets each by a linear blit of the one above (a 2x2 box filter; for an sRGB
  /// format the device filters linear values, Vulkan 1.0 "Image Copies with Scaling").
  void upload(Image& image, const void* texels, size_t bytesPerTexel);
  /// Whether images of `format` can be sampled with linear filtering.
  bool canSampleLinear(VkFormat format) const;
  /// Reads back an RGBA32F image created with TRANSFER_SRC usage, currently in `layout`.
  std::vector<float> download(const Image& image, VkImageLayout layout);

  /// Records commands with `record` into a one-time command buffer, submits and waits.
  template <typename F>
  void submit(F record) {
    VkCommandBuffer cmd = begin();
    record(cmd);
    end(cmd);
  }

  /// An image layout transition barrier on mip levels [baseLevel, baseLevel + levelCount) of a
  /// colour image (by default its only level).
  static void transition(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                         VkAccessFlags srcAccess, VkAccessFlags dstAccess, VkPipelineStageFlags srcStage,
                         VkPipelineStageFlags dstStage, uint32_t baseLevel = 0, uint32_t levelCount = 1);

 private:
  uint32_t memoryType(uint32_t typeBits, VkMemoryPropertyFlags properties) const;
  Image createImageLevels(uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage,
                          VkSamplerAddressMode addressU, VkSamplerAddressMode addressV, uint32_t mipLevels);
  VkCommandBuffer begin();
  void end(VkCommandBuffer cmd);

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  std::string deviceName_;
  uint32_t maxImageDimension2D_ = 4096;  // the least any Vulkan 1.0 device guarantees
  VkPhysicalDeviceLimits limits_{};
  std::unique_ptr<std::vector<std::string>> messages_ = std::make_unique<std::vector<std::string>>();
};

}  // namespace mxc::rt
