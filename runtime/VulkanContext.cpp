#include "runtime/VulkanContext.h"

#include <mutex>

#include <algorithm>
#include <cstring>

#include <fmt/format.h>

namespace mxc::rt {

void check(VkResult result, const char* what) {
  if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY) {
    throw VulkanOutOfMemory(fmt::format("{} failed: {} memory ran out", what,
                                        result == VK_ERROR_OUT_OF_DEVICE_MEMORY ? "the device's" : "the host's"));
  }
  if (result != VK_SUCCESS) throw VulkanError(fmt::format("{} failed (VkResult {})", what, static_cast<int>(result)));
}

namespace {

VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                         VkDebugUtilsMessageTypeFlagsEXT, const VkDebugUtilsMessengerCallbackDataEXT* data,
                                         void* user) {
  if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
    // Called on whichever thread made the Vulkan call (the renderer creates pipelines on
    // several); the list is read only once those calls have returned.
    static std::mutex mutex;
    std::lock_guard<std::mutex> lock(mutex);
    static_cast<std::vector<std::string>*>(user)->push_back(data->pMessage ? data->pMessage : "(no message)");
  }
  return VK_FALSE;
}

bool hasLayer(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

std::string_view typeName(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
    default: return "other";
  }
}

VkInstance createInstance(bool validation, std::vector<std::string>* messages, VkDebugUtilsMessengerEXT* messenger) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "mxc";
  app.apiVersion = VK_API_VERSION_1_1;
  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  const bool useValidation = validation && hasLayer("VK_LAYER_KHRONOS_validation");
  if (validation && !useValidation) throw VulkanError("the Vulkan validation layer VK_LAYER_KHRONOS_validation is not installed");
  if (useValidation) {
    layers.push_back("VK_LAYER_KHRONOS_validation");
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }
  VkDebugUtilsMessengerCreateInfoEXT debug{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  debug.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  debug.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                      VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  debug.pfnUserCallback = onMessage;
  debug.pUserData = messages;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  if (useValidation) info.pNext = &debug;
  VkInstance instance = VK_NULL_HANDLE;
  VkResult result = vkCreateInstance(&info, nullptr, &instance);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER) {
    throw VulkanError("no Vulkan driver found: install mesa-vulkan-drivers (lavapipe) or a GPU driver");
  }
  check(result, "vkCreateInstance");
  if (useValidation) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
    if (create) check(create(instance, &debug, nullptr, messenger), "vkCreateDebugUtilsMessengerEXT");
  }
  return instance;
}

}  // namespace

std::vector<std::string> VulkanContext::describeDevices() {
  VkInstance instance = VK_NULL_HANDLE;
  try {
    instance = createInstance(false, nullptr, nullptr);
  } catch (const VulkanError& e) {
    return {e.what()};
  }
  uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance, &count, devices.data());
  std::vector<std::string> out;
  for (uint32_t i = 0; i < count; ++i) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(devices[i], &p);
    std::string line = fmt::format("{}: {} ({}), Vulkan {}.{}.{}", i, p.deviceName, typeName(p.deviceType),
                                   VK_API_VERSION_MAJOR(p.apiVersion), VK_API_VERSION_MINOR(p.apiVersion),
                                   VK_API_VERSION_PATCH(p.apiVersion));
    // The driver's name and version: VK_KHR_driver_properties (core in 1.2), chained only when
    // the device has it.
    uint32_t extensionCount = 0;
    vkEnumerateDeviceExtensionProperties(devices[i], nullptr, &extensionCount, nullptr);
    std::vector<VkExtensionProperties> extensions(extensionCount);
    vkEnumerateDeviceExtensionProperties(devices[i], nullptr, &extensionCount, extensions.data());
    bool driverProperties = false;
    for (const VkExtensionProperties& e : extensions) {
      driverProperties = driverProperties || std::strcmp(e.extensionName, VK_KHR_DRIVER_PROPERTIES_EXTENSION_NAME) == 0;
    }
    if (driverProperties) {
      VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
      VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
      properties.pNext = &driver;
      vkGetPhysicalDeviceProperties2(devices[i], &properties);
      line += fmt::format(", driver {} {}", driver.driverName, driver.driverInfo);
    }
    out.push_back(std::move(line));
  }
  if (out.empty()) out.push_back("Vulkan reports no device: install mesa-vulkan-drivers for lavapipe");
  vkDestroyInstance(instance, nullptr);
  return out;
}

VulkanContext::VulkanContext(const DeviceOptions& options) {
  instance_ = createInstance(options.validation, messages_.get(), &messenger_);
  uint32_t count = 0;
  vkEnumeratePhysicalDevices(instance_, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(instance_, &count, devices.data());
  if (devices.empty()) throw VulkanError("Vulkan reports no device: install mesa-vulkan-drivers for lavapipe");
  std::vector<VkPhysicalDeviceProperties> properties(count);
  for (uint32_t i = 0; i < count; ++i) vkGetPhysicalDeviceProperties(devices[i], &properties[i]);
  int chosen = -1;
  if (options.device.empty()) {
    // Lavapipe by default: deterministic, and what CI has.
    for (uint32_t i = 0; i < count && chosen < 0; ++i) {
      if (std::strstr(properties[i].deviceName, "llvmpipe")) chosen = static_cast<int>(i);
    }
    if (chosen < 0) chosen = 0;
  } else if (std::all_of(options.device.begin(), options.device.end(), ::isdigit)) {
    chosen = std::stoi(options.device);
    if (chosen >= static_cast<int>(count)) {
      throw VulkanError(fmt::format("no Vulkan device {} (there are {})", options.device, count));
    }
  } else {
    for (uint32_t i = 0; i < count && chosen < 0; ++i) {
      if (std::strstr(properties[i].deviceName, options.device.c_str())) chosen = static_cast<int>(i);
    }
    if (chosen < 0) throw VulkanError(fmt::format("no Vulkan device named like '{}'", options.device));
  }
  physical_ = devices[static_cast<size_t>(chosen)];
  deviceName_ = properties[static_cast<size_t>(chosen)].deviceName;
  maxImageDimension2D_ = properties[static_cast<size_t>(chosen)].limits.maxImageDimension2D;
  limits_ = properties[static_cast<size_t>(chosen)].limits;

  uint32_t families = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &families, nullptr);
  std::vector<VkQueueFamilyProperties> familyProperties(families);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &families, familyProperties.data());
  bool found = false;
  for (uint32_t i = 0; i < families && !found; ++i) {
    const VkQueueFlags need = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    if ((familyProperties[i].queueFlags & need) == need) queueFamily_ = i, found = true;
  }
  if (!found) throw VulkanError(fmt::format("device {} has no queue for both graphics and compute", deviceName_));
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = queueFamily_;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;
  VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
  deviceInfo.queueCreateInfoCount = 1;
  deviceInfo.pQueueCreateInfos = &queueInfo;
  check(vkCreateDevice(physical_, &deviceInfo, nullptr, &device_), "vkCreateDevice");
  vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.queueFamilyIndex = queueFamily_;
  poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  check(vkCreateCommandPool(device_, &poolInfo, nullptr, &pool_), "vkCreateCommandPool");
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  check(vkCreateFence(device_, &fenceInfo, nullptr, &fence_), "vkCreateFence");
}

VulkanContext::~VulkanContext() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    vkDestroyFence(device_, fence_, nullptr);
    vkDestroyCommandPool(device_, pool_, nullptr);
    vkDestroyDevice(device_, nullptr);
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
  }
  if (instance_) vkDestroyInstance(instance_, nullptr);
}

uint32_t VulkanContext::memoryType(uint32_t typeBits, VkMemoryPropertyFlags properties) const {
  VkPhysicalDeviceMemoryProperties memory;
  vkGetPhysicalDeviceMemoryProperties(physical_, &memory);
  for (uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
    if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & properties) == properties) return i;
  }
  throw VulkanError("no suitable Vulkan memory type");
}

Buffer VulkanContext::createBuffer(VkDeviceSize size, VkBufferUsageFlags usage) {
  Buffer b;
  b.size = std::max<VkDeviceSize>(size, 16);
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = b.size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  check(vkCreateBuffer(device_, &info, nullptr, &b.buffer), "vkCreateBuffer");
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device_, b.buffer, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex =
      memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  check(vkAllocateMemory(device_, &alloc, nullptr, &b.memory), "vkAllocateMemory");
  check(vkBindBufferMemory(device_, b.buffer, b.memory, 0), "vkBindBufferMemory");
  check(vkMapMemory(device_, b.memory, 0, VK_WHOLE_SIZE, 0, &b.mapped), "vkMapMemory");
  return b;
}

void VulkanContext::destroy(Buffer& b) {
  if (b.memory) vkFreeMemory(device_, b.memory, nullptr);
  if (b.buffer) vkDestroyBuffer(device_, b.buffer, nullptr);
  b = Buffer{};
}

Image VulkanContext::createImage(uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage,
                                 VkSamplerAddressMode addressU, VkSamplerAddressMode addressV) {
  return createImageLevels(width, height, format, usage, addressU, addressV, 1);
}

Image VulkanContext::createTexture(uint32_t width, uint32_t height, VkFormat format) {
  VkFormatProperties properties{};
  vkGetPhysicalDeviceFormatProperties(physical_, format, &properties);
  const VkFormatFeatureFlags blit =
      VK_FORMAT_FEATURE_BLIT_SRC_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT;
  uint32_t levels = 1;
  if ((properties.optimalTilingFeatures & blit) == blit) {
    // Down to 1x1: floor(log2(max side)) + 1 levels (Vulkan's full mip chain).
    for (uint32_t side = std::max(width, height); side > 1; side /= 2) ++levels;
  }
  const VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                  (levels > 1 ? VkImageUsageFlags{VK_IMAGE_USAGE_TRANSFER_SRC_BIT} : VkImageUsageFlags{0});
  return createImageLevels(width, height, format, usage, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE,
                           VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, levels);
}

Image VulkanContext::createImageLevels(uint32_t width, uint32_t height, VkFormat format, VkImageUsageFlags usage,
                                       VkSamplerAddressMode addressU, VkSamplerAddressMode addressV,
                                       uint32_t mipLevels) {
  // vkCreateImage with an extent past the device's limit is undefined behaviour (VUID-VkImageCreateInfo-extent-02252).
  if (width == 0 || height == 0 || width > maxImageDimension2D_ || height > maxImageDimension2D_) {
    throw VulkanError(fmt::format("an image of {}x{} is beyond the device's limit of {} per side", width, height,
                                  maxImageDimension2D_));
  }
  Image img;
  img.width = width;
  img.height = height;
  img.format = format;
  img.mipLevels = mipLevels;
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {width, height, 1};
  info.mipLevels = mipLevels;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  check(vkCreateImage(device_, &info, nullptr, &img.image), "vkCreateImage");
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(device_, img.image, &req);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = req.size;
  alloc.memoryTypeIndex = memoryType(req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  check(vkAllocateMemory(device_, &alloc, nullptr, &img.memory), "vkAllocateMemory");
  check(vkBindImageMemory(device_, img.image, img.memory, 0), "vkBindImageMemory");
  VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  view.image = img.image;
  view.viewType = VK_IMAGE_VIEW_TYPE_2D;
  view.format = format;
  const bool depth = format == VK_FORMAT_D32_SFLOAT;
  view.subresourceRange = {static_cast<VkImageAspectFlags>(depth ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT),
                           0, mipLevels, 0, 1};
  check(vkCreateImageView(device_, &view, nullptr, &img.view), "vkCreateImageView");
  if (usage & VK_IMAGE_USAGE_SAMPLED_BIT) {
    VkSamplerCreateInfo sampler{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sampler.magFilter = VK_FILTER_LINEAR;
    sampler.minFilter = VK_FILTER_LINEAR;
    sampler.mipmapMode = mipLevels > 1 ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sampler.addressModeU = addressU;
    sampler.addressModeV = addressV;
    sampler.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    sampler.maxLod = static_cast<float>(mipLevels - 1);
    check(vkCreateSampler(device_, &sampler, nullptr, &img.sampler), "vkCreateSampler");
  }
  return img;
}

void VulkanContext::destroy(Image& img) {
  if (img.sampler) vkDestroySampler(device_, img.sampler, nullptr);
  if (img.view) vkDestroyImageView(device_, img.view, nullptr);
  if (img.image) vkDestroyImage(device_, img.image, nullptr);
  if (img.memory) vkFreeMemory(device_, img.memory, nullptr);
  img = Image{};
}

void VulkanContext::upload(Image& img, const float* rgba) { upload(img, rgba, 4 * sizeof(float)); }

bool VulkanContext::canSampleLinear(VkFormat format) const {
  VkFormatProperties properties{};
  vkGetPhysicalDeviceFormatProperties(physical_, format, &properties);
  const VkFormatFeatureFlags needed = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT |
                                      VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
  return (properties.optimalTilingFeatures & needed) == needed;
}

void VulkanContext::upload(Image& img, const void* texels, size_t bytesPerTexel) {
  const VkDeviceSize bytes = VkDeviceSize{img.width} * img.height * bytesPerTexel;
  Buffer staging = createBuffer(bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
  std::memcpy(staging.mapped, texels, bytes);
  submit([&](VkCommandBuffer cmd) {
    transition(cmd, img.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
               VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {img.width, img.height, 1};
    vkCmdCopyBufferToImage(cmd, staging.buffer, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    // Each further level from the one above it: that level becomes a blit source, the blit
    // halves each side (never below 1).
    const VkPipelineStageFlags transfer = VK_PIPELINE_STAGE_TRANSFER_BIT;
    for (uint32_t level = 1; level < img.mipLevels; ++level) {
      transition(cmd, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                 VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_TRANSFER_READ_BIT, transfer, transfer, level - 1, 1);
      if (level == 1) {
        transition(cmd, img.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
                   VK_ACCESS_TRANSFER_WRITE_BIT, transfer, transfer, 1, img.mipLevels - 1);
      }
      auto side = [&](uint32_t full, uint32_t l) { return static_cast<int32_t>(std::max(full >> l, 1u)); };
      VkImageBlit blit{};
      blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, 1};
      blit.srcOffsets[1] = {side(img.width, level - 1), side(img.height, level - 1), 1};
      blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, 1};
      blit.dstOffsets[1] = {side(img.width, level), side(img.height, level), 1};
      vkCmdBlitImage(cmd, img.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                     1, &blit, VK_FILTER_LINEAR);
    }
    const VkPipelineStageFlags shaders = VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
    if (img.mipLevels > 1) {
      transition(cmd, img.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                 VK_ACCESS_TRANSFER_READ_BIT, VK_ACCESS_SHADER_READ_BIT, transfer, shaders, 0, img.mipLevels - 1);
    }
    transition(cmd, img.image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
               VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT, transfer, shaders, img.mipLevels - 1, 1);
  });
  destroy(staging);
}

std::vector<float> VulkanContext::download(const Image& img, VkImageLayout layout) {
  const VkDeviceSize bytes = VkDeviceSize{img.width} * img.height * 4 * sizeof(float);
  Buffer staging = createBuffer(bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
  submit([&](VkCommandBuffer cmd) {
    transition(cmd, img.image, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
               VK_ACCESS_TRANSFER_READ_BIT, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {img.width, img.height, 1};
    vkCmdCopyImageToBuffer(cmd, img.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.buffer, 1, &region);
    transition(cmd, img.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout, VK_ACCESS_TRANSFER_READ_BIT,
               VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
               VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT);
  });
  std::vector<float> out(bytes / sizeof(float));
  std::memcpy(out.data(), staging.mapped, bytes);
  destroy(staging);
  return out;
}

VkCommandBuffer VulkanContext::begin() {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  check(vkAllocateCommandBuffers(device_, &alloc, &cmd), "vkAllocateCommandBuffers");
  VkCommandBufferBeginInfo info{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd, &info), "vkBeginCommandBuffer");
  return cmd;
}

void VulkanContext::end(VkCommandBuffer cmd) {
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  check(vkResetFences(device_, 1, &fence_), "vkResetFences");
  check(vkQueueSubmit(queue_, 1, &submit, fence_), "vkQueueSubmit");
  check(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
  vkFreeCommandBuffers(device_, pool_, 1, &cmd);
}

void VulkanContext::transition(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                               VkAccessFlags srcAccess, VkAccessFlags dstAccess, VkPipelineStageFlags srcStage,
                               VkPipelineStageFlags dstStage, uint32_t baseLevel, uint32_t levelCount) {
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcAccessMask = srcAccess;
  barrier.dstAccessMask = dstAccess;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, baseLevel, levelCount, 0, 1};
  vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

}  // namespace mxc::rt
