#include "cli/AccuracyBench.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <limits>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "cli/AccuracyReport.h"
#include "cli/ExitCode.h"
#include "cli/MaterialPipeline.h"
#include "cli/OutputSet.h"
#include "compiler/spirv/SpirvCompiler.h"
#include "runtime/Evaluator.h"
#include "runtime/Renderer.h"

namespace mxc::cli {

namespace {

namespace fs = std::filesystem;
/// The error images are compared as kImageBlocks x kImageBlocks blocks (blockLuminance).
constexpr uint32_t kImageBlocks = 16;
using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// One material of the bench: a document's material, with --set overrides.
struct BenchMaterial {
  std::string name;
  fs::path file;
  std::vector<std::string> set;
  std::string material;  ///< the document's material (empty: its only one)
};

/// The fixed set: both shading models' parameters through OpenPBR presets and examples, covering
/// a dielectric base, coat, metal, glass, subsurface, fuzz, thin film and emission, and rough
/// variants where the tiers differ most (multiple scattering).
std::vector<BenchMaterial> fixedSet(const fs::path& corpus) {
  const fs::path presets = corpus / "openpbr-presets";
  const fs::path examples = corpus / "materialx" / "examples" / "OpenPbr";
  return {
      {"open_pbr_default", presets / "open_pbr_default.mtlx", {}, {}},
      {"carpaint (coat)", presets / "open_pbr_carpaint.mtlx", {}, {}},
      {"glass", presets / "open_pbr_glass.mtlx", {}, {}},
      {"brass (metal)", presets / "open_pbr_brass.mtlx", {}, {}},
      {"marble (subsurface)", presets / "open_pbr_marble.mtlx", {}, {}},
      {"velvet (fuzz)", examples / "open_pbr_velvet.mtlx", {}, {}},
      {"soap bubble (thin film)", examples / "open_pbr_soapbubble.mtlx", {}, {}},
      {"pearl", examples / "open_pbr_pearl.mtlx", {}, {}},
      {"light bulb (emission)", presets / "open_pbr_light_bulb_5000k.mtlx", {}, {}},
      {"rough metal (r 0.6)", presets / "open_pbr_default.mtlx", {"base_metalness=1", "specular_roughness=0.6"}, {}},
      {"rough glass (r 0.5)", presets / "open_pbr_glass.mtlx", {"specular_roughness=0.5"}, {}},
      {"rough coat (r 0.3)", presets / "open_pbr_default.mtlx", {"coat_weight=1", "coat_roughness=0.3"}, {}},
  };
}

double luminance(glm::vec3 v) { return 0.2126 * v.x + 0.7152 * v.y + 0.0722 * v.z; }

/// The view angles of the albedo: 0, 10, ..., 80 degrees.
std::vector<glm::vec3> albedoViews() {
  std::vector<glm::vec3> views;
  for (int k = 0; k <= 8; ++k) {
    const double theta = glm::radians(10.0 * k);
    views.emplace_back(float(std::sin(theta)), 0.0f, float(std::cos(theta)));
  }
  return views;
}

glm::vec3 direction(double thetaDeg, double phiDeg) {
  const double t = glm::radians(thetaDeg), p = glm::radians(phiDeg);
  return glm::vec3(float(std::sin(t) * std::cos(p)), float(std::sin(t) * std::sin(p)), float(std::cos(t)));
}

/// The direction pairs of f cos: views at 0, 30, 60 and 80 degrees; light directions at 15, 45
/// and 75 degrees in the plane of incidence (both sides) and across it, and transmitted ones at
/// 135 and 165 degrees.
std::vector<rt::DirectionPair> evalPairs() {
  std::vector<rt::DirectionPair> pairs;
  for (double view : {0.0, 30.0, 60.0, 80.0}) {
    const glm::vec3 wo = direction(view, 0.0);
    for (double theta : {15.0, 45.0, 75.0}) {
      for (double phi : {0.0, 90.0, 180.0}) pairs.push_back({wo, direction(theta, phi)});
    }
    for (double theta : {135.0, 165.0}) {
      for (double phi : {0.0, 180.0}) pairs.push_back({wo, direction(theta, phi)});
    }
  }
  return pairs;
}

/// A running Monte Carlo estimate of many values from batches of unequal sizes: the mean, and
/// its standard error from the spread of the batch means (Var(batch mean) = sigma^2 / size, so
/// sum size_b (mean_b - mean)^2 estimates sigma^2 (B - 1)).
class BatchEstimate {
 public:
  void add(std::vector<double> values, double size) {
    batches_.push_back(std::move(values));
    sizes_.push_back(size);
  }
  double size() const {
    double n = 0;
    for (double s : sizes_) n += s;
    return n;
  }
  std::vector<double> mean() const {
    std::vector<double> m(batches_.at(0).size(), 0.0);
    const double n = size();  // > 0: at least one batch of size > 0
    for (size_t b = 0; b < batches_.size(); ++b) {
      for (size_t i = 0; i < m.size(); ++i) m[i] += sizes_[b] * batches_[b][i] / n;
    }
    return m;
  }
  /// The error measure (normalisedRms) of one standard error: the estimate's own noise, in the
  /// units of the errors it measures.
  double noise() const;
  /// Needs two batches or more (B - 1 > 0).
  std::vector<double> standardError() const {
    const std::vector<double> m = mean();
    std::vector<double> se(m.size(), 0.0);
    const double n = size(), dof = double(batches_.size()) - 1.0;
    for (size_t b = 0; b < batches_.size(); ++b) {
      for (size_t i = 0; i < m.size(); ++i) se[i] += sizes_[b] * (batches_[b][i] - m[i]) * (batches_[b][i] - m[i]);
    }
    for (double& v : se) v = std::sqrt(v / dof / n);  // sqrt of a sum of squares >= 0
    return se;
  }

 private:
  std::vector<std::vector<double>> batches_;
  std::vector<double> sizes_;
};

/// Relative RMS error, value by value: an albedo of 0 in the reference would make any value an
/// infinite error, hence max(reference, 1e-3).
double relativeRms(const std::vector<double>& values, const std::vector<double>& reference) {
  double sum = 0.0;
  for (size_t i = 0; i < reference.size(); ++i) {
    const double d = (values[i] - reference[i]) / std::max(reference[i], 1e-3);
    sum += d * d;
  }
  return std::sqrt(sum / double(reference.size()));  // reference is not empty
}

/// Mean absolute difference over the views and the three channels.
double meanAbsolute(const std::vector<glm::vec3>& values, const std::vector<glm::dvec3>& reference) {
  double sum = 0.0;
  for (size_t k = 0; k < reference.size(); ++k) {
    for (int c = 0; c < 3; ++c) sum += std::abs(double(values[k][c]) - reference[k][c]);
  }
  return reference.empty() ? NAN : sum / (3.0 * double(reference.size()));  // > 0 views
}

/// RMS error over the reference's RMS: the relative error of a signal with zeros and peaks
/// (f cos, an image). NaN when the reference is 0 everywhere.
double normalisedRms(const std::vector<double>& values, const std::vector<double>& reference) {
  double error = 0.0, signal = 0.0;
  for (size_t i = 0; i < reference.size(); ++i) {
    error += (values[i] - reference[i]) * (values[i] - reference[i]);
    signal += reference[i] * reference[i];
  }
  return signal > 1e-20 ? std::sqrt(error / signal) : NAN;  // signal > 0
}

double BatchEstimate::noise() const {
  const std::vector<double> m = mean(), se = standardError();
  std::vector<double> upper(m.size());
  for (size_t i = 0; i < m.size(); ++i) upper[i] = m[i] + se[i];
  return normalisedRms(upper, m);
}

/// The smallest error of the other tiers; the reference refines until its noise is below half
/// of it. Infinity when no tier has a defined error.
double refineTarget(const std::vector<TierFigures>& tiers, double TierFigures::*figure) {
  double smallest = std::numeric_limits<double>::infinity();
  for (const TierFigures& t : tiers) {
    if (std::isfinite(t.*figure)) smallest = std::min(smallest, t.*figure);
  }
  return 0.5 * smallest;
}

/// The image's luminance averaged over kImageBlocks x kImageBlocks square blocks (the image's
/// size is a multiple of kImageBlocks). A walk's radiance is noisy (a relative noise of about
/// 0.5 per pixel and frame on open_pbr_default): averaging blocks of b x b pixels divides the
/// reference's noise by b while a tier's bias, smooth over a sphere, stays, so that thousands of
/// frames are not needed to resolve it.
std::vector<double> blockLuminance(const rt::RgbaImage& image) {
  const uint32_t block = image.width / kImageBlocks;  // >= 1: the size is checked
  std::vector<double> l(size_t(kImageBlocks) * kImageBlocks, 0.0);
  for (uint32_t y = 0; y < block * kImageBlocks; ++y) {
    for (uint32_t x = 0; x < block * kImageBlocks; ++x) {
      const float* p = image.at(x, y);
      l[size_t(y / block) * kImageBlocks + x / block] += luminance(glm::vec3(p[0], p[1], p[2])) / double(block * block);
    }
  }
  return l;
}

/// One material's measurements at one tier.
class TierRun {
 public:
  TierRun(const BenchMaterial& m, Accuracy tier, const AccuracyBenchOptions& options)
      : pipeline_(session_) {
    MaterialOptions materials;
    materials.set = m.set;
    materials.material = m.material;
    materials.accuracy = tier;
    materials.referenceSamples = 1;  // eval averages dispatches of one walk (rt::MaterialKernel)
    materials.libraries = options.libraries;
    CompileRequest request;
    request.document = m.file;
    status_ = pipeline_.run(std::move(request), materials);
  }
  int status() const { return status_; }
  const ir::Material& material() { return pipeline_.materials().at(0); }
  /// The furnace, eval and raster programs; nullopt when one does not compile (printed).
  std::optional<std::array<MaterialProgram, 3>> programs(rt::VulkanContext& context) {
    std::array<MaterialProgram, 3> out;
    const glsl::ShaderKind kinds[3] = {glsl::ShaderKind::Furnace, glsl::ShaderKind::Eval, glsl::ShaderKind::Raster};
    for (int k = 0; k < 3; ++k) {
      auto p = prepareMaterial(pipeline_, session_, context, material(), kinds[k]);
      if (!p) return std::nullopt;
      out[k] = std::move(*p);
    }
    return out;
  }

 private:
  Session session_;
  MaterialPipeline pipeline_;
  int status_ = kOk;
};

/// What one material's measurement needs from the run.
struct BenchContext {
  const AccuracyBenchOptions& options;
  rt::VulkanContext& context;
  rt::AlbedoTables& tables;
  rt::Renderer& renderer;
  const rt::Mesh& sphere;
  std::vector<glm::vec3> views = albedoViews();
  std::vector<rt::DirectionPair> pairs = evalPairs();
};

/// The scene of the images: a sphere under the analytic sky, with `mxc render`'s default key
/// light when `keyLight`. The error images have no key light: a directional light's highlight on
/// a near-mirror (brass, roughness 0.02) is far smaller than a pixel, and the frames' sub-pixel
/// jitter then makes every estimate of it so noisy that thousands of frames would not resolve a
/// tier's error; lights are measured by f cos instead. The frame time has it, as a render does.
rt::RenderSettings sceneSettings(uint32_t size, uint32_t frames, bool keyLight) {
  rt::RenderSettings s;
  s.width = s.height = size;
  s.frames = frames;
  s.environment = rt::Environment::Sky;
  if (keyLight) {
    s.lights.push_back({rt::Light::Kind::Directional, glm::normalize(glm::vec3(-1.0f, 1.2f, 1.5f)), glm::vec3(1.0f), 2.0f});
  }
  return s;
}

/// The estimates of one tier, before the errors are taken against the reference.
struct TierEstimates {
  std::vector<double> albedo, albedoError;  ///< per view; the standard error of each
  std::vector<glm::vec3> albedoRgb;         ///< per view, per channel
  BatchEstimate fcos;                       ///< per direction pair
  BatchEstimate image;                      ///< per pixel
  TierFigures figures;
};

/// The cost figures: ns per evaluation (with the tier's evaluator, already built: a pipeline
/// takes seconds on lavapipe), ms per frame, instruction count.
void measureCost(BenchContext& bench, rt::MaterialEvaluator& evaluator, const MaterialProgram& raster,
                 TierFigures& figures, bool reference) {
  std::vector<rt::DirectionPair> many;
  while (many.size() < (size_t{1} << 16)) many.insert(many.end(), bench.pairs.begin(), bench.pairs.end());
  double best = std::numeric_limits<double>::infinity();
  for (int r = 0; r < 3; ++r) {
    const auto start = Clock::now();
    evaluator.evaluate(many, 1, 1000 + r);
    best = std::min(best, secondsSince(start));
  }
  figures.nsPerEval = best * 1e9 / double(many.size());
  const uint32_t size = uint32_t(bench.options.frameSize);
  figures.msPerFrame = bench.renderer
                           .render(bench.sphere, *raster.resources, raster.shader.interface, raster.spirv,
                                   sceneSettings(size, reference ? 3 : 6, true))
                           .msPerFrame;
  figures.spirvInstructions = spirv::instructionCount(raster.spirv);
}

void log(const std::string& line) { std::fprintf(stderr, "%s\n", line.c_str()); }

/// fast or balanced: deterministic but for their own sampling, at fixed, generous counts.
std::optional<TierEstimates> measureTier(BenchContext& bench, const BenchMaterial& m, Accuracy tier) {
  TierRun run(m, tier, bench.options);
  if (run.status() != kOk) return std::nullopt;
  auto programs = run.programs(bench.context);
  if (!programs) return std::nullopt;
  auto& [furnace, eval, raster] = *programs;
  TierEstimates out;
  out.figures.tier = tier;
  rt::FurnaceEstimator estimator(bench.context, bench.tables, *furnace.resources, furnace.shader.interface,
                                 furnace.spirv);
  for (const rt::Albedo& a : estimator.estimate(bench.views, 1u << 20, 1)) {
    out.albedo.push_back(luminance(a.total()));
    out.albedoRgb.push_back(a.total());
    out.albedoError.push_back(luminance(a.reflectedError) + luminance(a.transmittedError));
  }
  rt::MaterialEvaluator evaluator(bench.context, bench.tables, *eval.resources, eval.shader.interface, eval.spirv);
  std::vector<double> fcos;
  for (const glm::vec4& v : evaluator.evaluate(bench.pairs)) fcos.push_back(luminance(glm::vec3(v)));
  out.fcos.add(std::move(fcos), 1.0);
  const uint32_t size = uint32_t(bench.options.imageSize);
  rt::RenderResult image = bench.renderer.render(bench.sphere, *raster.resources, raster.shader.interface,
                                                 raster.spirv, sceneSettings(size, uint32_t(bench.options.tierFrames), false));
  out.image.add(blockLuminance(image.image), 1.0);
  measureCost(bench, evaluator, raster, out.figures, false);
  return out;
}

/// The reference: each estimate refined (x4 walks or frames) until its noise is below half the
/// other tiers' smallest error against it, or its cap.
std::optional<MaterialFigures> measureMaterial(BenchContext& bench, const BenchMaterial& m) {
  const AccuracyBenchOptions& o = bench.options;
  std::vector<TierEstimates> tiers;
  for (Accuracy tier : kAccuracies) {
    if (tier == Accuracy::Reference) continue;
    log(fmt::format("{}: {}", m.name, accuracyName(tier)));
    auto t = measureTier(bench, m, tier);
    if (!t) return std::nullopt;
    tiers.push_back(std::move(*t));
  }
  auto others = [&] {
    std::vector<TierFigures> f;
    for (const TierEstimates& t : tiers) f.push_back(t.figures);
    return f;
  };

  TierRun run(m, Accuracy::Reference, o);
  if (run.status() != kOk) return std::nullopt;
  auto programs = run.programs(bench.context);
  if (!programs) return std::nullopt;
  auto& [furnace, eval, raster] = *programs;
  MaterialFigures out;
  out.name = m.name;
  out.source = m.file.filename().string();
  for (const std::string& s : m.set) out.source += " --set " + s;
  if (!m.material.empty()) out.source += " --material " + m.material;
  TierFigures ref;
  ref.tier = Accuracy::Reference;

  // The albedo: the furnace's own standard errors, combined over rounds of n_r walks per view
  // as SE^2 = sum n_r^2 SE_r^2 / N^2.
  {
    rt::FurnaceEstimator estimator(bench.context, bench.tables, *furnace.resources, furnace.shader.interface,
                                   furnace.spirv);
    const size_t views = bench.views.size();
    std::vector<double> sum(views, 0.0), variance(views, 0.0);
    std::vector<glm::dvec3> sumRgb(views, glm::dvec3(0.0)), varianceRgb(views, glm::dvec3(0.0));
    uint32_t total = 0, next = std::min<uint32_t>(uint32_t(o.albedoWalks), 16384), round = 0;
    std::vector<double> mean(views), error(views);
    const auto start = Clock::now();
    while (true) {
      const auto albedo = estimator.estimate(bench.views, next, 1 + round++);
      total += next;
      for (size_t k = 0; k < views; ++k) {
        sum[k] += double(next) * luminance(albedo[k].total());
        const double se = luminance(albedo[k].reflectedError) + luminance(albedo[k].transmittedError);
        variance[k] += double(next) * double(next) * se * se;
        mean[k] = sum[k] / total;                 // total > 0
        error[k] = std::sqrt(variance[k]) / total;  // sqrt of a sum of squares
        const glm::dvec3 seRgb = glm::dvec3(albedo[k].reflectedError) + glm::dvec3(albedo[k].transmittedError);
        sumRgb[k] += double(next) * glm::dvec3(albedo[k].total());
        varianceRgb[k] += double(next) * double(next) * seRgb * seRgb;
      }
      for (TierEstimates& t : tiers) t.figures.albedoError = relativeRms(t.albedo, mean);
      std::vector<double> upper(views);
      for (size_t k = 0; k < views; ++k) upper[k] = mean[k] + error[k];
      ref.albedoError = relativeRms(upper, mean);
      log(fmt::format("{}: reference albedo, {} walks per view: noise {:.5f} ({:.1f} s)", m.name, total,
                      ref.albedoError, secondsSince(start)));
      if (ref.albedoError <= refineTarget(others(), &TierFigures::albedoError) || total >= uint32_t(o.albedoWalks)) {
        break;
      }
      next = std::min<uint32_t>(3 * total, uint32_t(o.albedoWalks) - total);
    }
    out.reference.albedoWalks = total;
    out.reference.albedoSeconds = secondsSince(start);
    // The absolute measure, against the final estimate; the reference's own is its mean
    // standard error (the mean absolute deviation of a normal error is 0.8 of it: an upper
    // bound).
    std::vector<glm::dvec3> meanRgb(views);
    double noiseRgb = 0.0;
    for (size_t k = 0; k < views; ++k) {
      meanRgb[k] = sumRgb[k] / double(total);  // total > 0
      for (int c = 0; c < 3; ++c) noiseRgb += std::sqrt(varianceRgb[k][c]) / double(total) / (3.0 * double(views));
    }
    for (TierEstimates& t : tiers) t.figures.albedoMeanAbs = meanAbsolute(t.albedoRgb, meanRgb);
    ref.albedoMeanAbs = noiseRgb;
  }

  // f cos: batches of walks per pair, seeds disjoint (dispatch d of a batch has seed first + d).
  rt::MaterialEvaluator evaluator(bench.context, bench.tables, *eval.resources, eval.shader.interface, eval.spirv);
  {
    BatchEstimate estimate;
    // The pairs repeated kReplicas times in one dispatch: a dispatch of 52 invocations would
    // leave the device idle. Every invocation has its own random stream.
    constexpr uint32_t kReplicas = 64;
    std::vector<rt::DirectionPair> replicated;
    for (uint32_t r = 0; r < kReplicas; ++r) replicated.insert(replicated.end(), bench.pairs.begin(), bench.pairs.end());
    uint32_t seed = 1;
    auto batch = [&](uint32_t walks) {
      const uint32_t dispatches = std::max<uint32_t>(walks / kReplicas, 1);
      const std::vector<glm::vec4> values = evaluator.evaluate(replicated, dispatches, seed);
      std::vector<double> mean(bench.pairs.size(), 0.0);
      for (size_t i = 0; i < values.size(); ++i) mean[i % mean.size()] += luminance(glm::vec3(values[i])) / kReplicas;
      seed += dispatches;
      estimate.add(std::move(mean), double(dispatches) * kReplicas);
    };
    const uint32_t first = std::max<uint32_t>(std::min<uint32_t>(uint32_t(o.evalWalks), 1024) / 4, 1);
    const auto start = Clock::now();
    for (int b = 0; b < 4; ++b) batch(first);
    while (true) {
      const std::vector<double> mean = estimate.mean();
      for (TierEstimates& t : tiers) t.figures.fcosError = normalisedRms(t.fcos.mean(), mean);
      ref.fcosError = estimate.noise();
      const uint32_t total = uint32_t(estimate.size());
      log(fmt::format("{}: reference f cos, {} walks per pair: noise {:.5f}", m.name, total, ref.fcosError));
      // A reference of 0 everywhere (every lobe a delta) has no error to resolve.
      if (!std::isfinite(ref.fcosError) || ref.fcosError <= refineTarget(others(), &TierFigures::fcosError) ||
          total >= uint32_t(o.evalWalks)) {
        out.reference.evalWalks = total;
        out.reference.evalSeconds = secondsSince(start);
        break;
      }
      // x4 in three batches, so that the spread has more batches to be measured from.
      const uint32_t add = std::min<uint32_t>(3 * total, uint32_t(o.evalWalks) - total);
      for (int b = 0; b < 3; ++b) batch(std::max<uint32_t>(add / 3, 1));
    }
  }

  // The image: batches of frames with disjoint frame indices (their own jitter and random numbers).
  {
    BatchEstimate estimate;
    uint32_t next = 0;
    double ms = 0.0;
    const uint32_t size = uint32_t(o.imageSize);
    auto batch = [&](uint32_t frames) {
      rt::RenderSettings s = sceneSettings(size, frames, false);
      s.firstFrame = next;
      rt::RenderResult r = bench.renderer.render(bench.sphere, *raster.resources, raster.shader.interface,
                                                 raster.spirv, s);
      next += frames;
      ms += r.msPerFrame * frames;
      estimate.add(blockLuminance(r.image), frames);
    };
    // Four batches first: the spread of fewer is too rough an estimate of the noise.
    const uint32_t first = std::max<uint32_t>(std::min<uint32_t>(uint32_t(o.imageFrames), 64) / 4, 1);
    for (int b = 0; b < 4; ++b) batch(first);
    while (true) {
      const std::vector<double> mean = estimate.mean();
      for (TierEstimates& t : tiers) t.figures.imageError = normalisedRms(t.image.mean(), mean);
      ref.imageError = estimate.noise();
      log(fmt::format("{}: reference image, {} frames: noise {:.5f} ({:.1f} s)", m.name, next, ref.imageError,
                      ms / 1000.0));
      if (!std::isfinite(ref.imageError) || ref.imageError <= refineTarget(others(), &TierFigures::imageError) ||
          next >= uint32_t(o.imageFrames)) {
        break;
      }
      // x4 in three batches, so that the spread has more batches to be measured from.
      const uint32_t add = std::min<uint32_t>(3 * next, uint32_t(o.imageFrames) - next);
      for (int b = 0; b < 3; ++b) batch(std::max<uint32_t>(add / 3, 1));
    }
    out.reference.imageFrames = next;
    out.reference.imageSeconds = ms / 1000.0;
  }
  measureCost(bench, evaluator, raster, ref, true);
  for (TierEstimates& t : tiers) out.tiers.push_back(t.figures);
  out.tiers.push_back(ref);
  return out;
}

std::string reproduce(const AccuracyBenchOptions& o) {
  const AccuracyBenchOptions d;
  std::string c = "mxc bench accuracy";
  if (o.albedoWalks != d.albedoWalks) c += fmt::format(" --albedo-walks {}", o.albedoWalks);
  if (o.evalWalks != d.evalWalks) c += fmt::format(" --eval-walks {}", o.evalWalks);
  if (o.imageFrames != d.imageFrames) c += fmt::format(" --image-frames {}", o.imageFrames);
  if (o.tierFrames != d.tierFrames) c += fmt::format(" --tier-frames {}", o.tierFrames);
  if (o.imageSize != d.imageSize) c += fmt::format(" --image-size {}", o.imageSize);
  if (o.frameSize != d.frameSize) c += fmt::format(" --frame-size {}", o.frameSize);
  if (o.reportDir != d.reportDir) c += " --report-dir " + o.reportDir;
  if (o.withFixedSet) c += " --fixed-set";
  for (const std::string& f : o.files) c += " " + f;
  return c;
}

}  // namespace

int runAccuracyBench(const AccuracyBenchOptions& options) {
  if (options.imageSize % kImageBlocks != 0) {
    std::fprintf(stderr, "error: --image-size %d: must be a multiple of %u (the error is taken over %ux%u blocks)\n",
                 options.imageSize, kImageBlocks, kImageBlocks, kImageBlocks);
    return kUsage;
  }
  // The materials: the fixed set, and (or instead) every material of each document given.
  std::vector<BenchMaterial> materials;
  if (options.files.empty() || options.withFixedSet) {
    const fs::path corpus = options.corpus.empty() ? fs::path(MXC_CORPUS_DIR) : fs::path(options.corpus);
    materials = fixedSet(corpus);
    for (const BenchMaterial& m : materials) {
      std::error_code ec;
      if (!fs::is_regular_file(m.file, ec)) {
        std::fprintf(stderr, "error: the fixed set's document '%s' is missing: pass --corpus DIR (the folder with "
                     "openpbr-presets/ and materialx/examples/) or documents\n", m.file.string().c_str());
        return kUsage;
      }
    }
  }
  {
    // A document of the fixed set measured as it is (no --set) is not measured twice.
    auto measured = [&](const fs::path& file) {
      std::error_code ec;
      for (const BenchMaterial& m : materials) {
        if (m.set.empty() && fs::equivalent(m.file, file, ec)) return true;
      }
      return false;
    };
    for (const std::string& file : options.files) {
      if (measured(file)) continue;
      Session session;
      MaterialPipeline pipeline(session);
      MaterialOptions all;
      all.libraries = options.libraries;
      CompileRequest request;
      request.document = file;
      if (int code = pipeline.run(std::move(request), all); code != kOk) return code;
      for (const ir::Material& m : pipeline.materials()) {
        materials.push_back({m.name, file, {}, pipeline.materials().size() > 1 ? m.name : std::string()});
      }
    }
  }

  // The outputs are declared (and refused) before minutes of measurement.
  if (printError(rt::loadImageModule())) return kOutputFailed;
  const fs::path dir = options.reportDir;
  const fs::path md = dir / "accuracy.md", csv = dir / "accuracy.csv", png = dir / "accuracy.png";
  OutputSet outputs;
  for (const fs::path& p : {md, csv, png}) {
    if (printError(outputs.declare(p, "--report-dir"))) return kOutputFailed;
  }
  for (const BenchMaterial& m : materials) {
    if (printError(outputs.checkNotInput(m.file, "a document"))) return kUsage;
  }

  Device device(options.device);
  rt::AlbedoTables* tables = device.tables();
  if (!tables) return kNoDevice;
  AccuracyReport report;
  report.device = device.context()->deviceName();
  report.command = reproduce(options);
  {
    const std::time_t now = std::time(nullptr);
    char date[32];
    std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
    report.date = date;
  }
  report.imageSize = uint32_t(options.imageSize);
  report.frameSize = uint32_t(options.frameSize);
  report.tierFrames = uint32_t(options.tierFrames);
  report.imageBlocks = kImageBlocks;
  try {
    rt::Renderer renderer(*device.context(), *tables);
    const rt::Mesh sphere = rt::makeSphere();
    BenchContext bench{options, *device.context(), *tables, renderer, sphere};
    report.views = uint32_t(bench.views.size());
    report.pairs = uint32_t(bench.pairs.size());
    for (size_t i = 0; i < materials.size(); ++i) {
      log(fmt::format("[{}/{}] {}", i + 1, materials.size(), materials[i].name));
      auto figures = measureMaterial(bench, materials[i]);
      if (!figures) return kInvalidDocument;
      report.materials.push_back(std::move(*figures));
    }
  } catch (const std::bad_alloc&) {
    throw;  // "out of memory", exit 4 (cli/Main.cpp)
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return kInvalidDocument;
  }
  if (!device.checkValidation()) return kInvalidDocument;

  auto plot = accuracyPlot(report);
  if (auto* why = std::get_if<std::string>(&plot)) {
    std::fprintf(stderr, "error: %s\n", why->c_str());
    return kOutputFailed;
  }
  auto encoded = rt::encodeImage(png, std::get<rt::RgbaImage>(plot), rt::ToneMapping::None);
  std::optional<std::string> error;
  if (auto* why = std::get_if<1>(&encoded)) error = *why;
  if (!error) error = outputs.stage(png, std::move(std::get<0>(encoded)));
  if (!error) error = outputs.stage(md, accuracyMarkdown(report));
  if (!error) error = outputs.stage(csv, accuracyCsv(report));
  if (!error) error = outputs.commit();
  if (printError(error)) return kOutputFailed;
  std::printf("wrote %s, %s and %s (%zu materials on %s)\n", md.string().c_str(), csv.string().c_str(),
              png.string().c_str(), report.materials.size(), report.device.c_str());
  const double fast = medianOver(report, Accuracy::Fast, &TierFigures::albedoError);
  const double balanced = medianOver(report, Accuracy::Balanced, &TierFigures::albedoError);
  std::printf("median relative albedo error: fast %.4f, balanced %.4f (balanced / fast %.3f)\n", fast, balanced,
              balanced / fast);
  return kOk;
}

}  // namespace mxc::cli
