#include "cli/SpecializationReport.h"

#include <algorithm>
#include <functional>
#include <string_view>

#include <fmt/format.h>

namespace mxc::cli {

namespace {

/// a / b, NaN unless both are finite and b > 0.
double ratio(double a, double b) { return std::isfinite(a) && std::isfinite(b) && b > 0.0 ? a / b : NAN; }

std::string number(double v, int digits = 1) { return std::isfinite(v) ? fmt::format("{:.{}f}", v, digits) : "-"; }

/// A cell that keeps the table's columns when the CSV is read back: no commas, no line ends.
std::string csvText(std::string s) {
  for (char& c : s) c = (c == ',' || c == '\n') ? ';' : c;
  return s;
}

size_t optimizedAt(const ShaderFigures& s, size_t scene) {
  return scene < s.optimized.size() ? s.optimized[scene] : 0;
}

template <typename F>
double medianOver(const SpecializationReport& r, F figure) {
  std::vector<double> v;
  for (const SpecializationRow& m : r.materials) v.push_back(figure(m));
  return medianOf(std::move(v));
}

bool endsWith(std::string_view s, std::string_view tail) { return s.size() >= tail.size() && s.ends_with(tail); }

/// The row of a material named by its file, or null.
const SpecializationRow* rowOf(const SpecializationReport& r, std::string_view file) {
  for (const SpecializationRow& m : r.materials) {
    if (endsWith(m.source, file)) return &m;
  }
  return nullptr;
}

std::string verdict(double measured, double target) {
  if (!std::isfinite(measured)) return "not measured";
  return measured <= target ? "met" : "**not met**";
}

}  // namespace

double medianOf(std::vector<double> values) {
  values.erase(std::remove_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }), values.end());
  if (values.empty()) return NAN;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);  // n >= 2 when even
}

double medianInstructionRatio(const SpecializationReport& r) {
  return medianOver(r, [](const SpecializationRow& m) {
    return ratio(double(m.specialized.shader.instructions), double(m.general.shader.instructions));
  });
}

double medianFrameRatio(const SpecializationReport& r, size_t scene) {
  return medianOver(r, [scene](const SpecializationRow& m) {
    return scene < m.specialized.scenes.size() && scene < m.general.scenes.size()
               ? ratio(m.specialized.scenes[scene].msPerFrame, m.general.scenes[scene].msPerFrame)
               : NAN;
  });
}

std::string specializationMarkdown(const SpecializationReport& r) {
  const size_t scenes = r.scenes.size();
  const bool mx = !r.materialxManifest.empty();
  std::string md;
  md += "# What specialization saves: specialized against general shaders\n\n";
  md += fmt::format("Written by `{}` on {}, {}. Every figure below comes from this one run; the ratios are what carries "
                    "over to another machine. docs/specialization.md says what is specialized and how.\n\n",
                    r.command, r.date, r.device);
  md += "- *general*: the shader a general-purpose generator makes (`--no-specialize`): every input of the shading node "
        "a uniform, every lobe of the shading model, the environment and the lights read at run time.\n";
  md += "- *specialized*: mxc's default: the document's values folded, unused lobes and library code not compiled, and "
        "the scene's environment, light count and light kinds fixed in the pipeline (specialization constants).\n";
  md += "- *instructions*: SPIR-V instructions of the fragment shader as compiled; *-O*: after SPIRV-Tools' performance "
        "passes (`mxc compile -O`), the specialized shader's with the scene's constants fixed first.\n";
  md += "- *to SPIR-V*: from the document to a validated module (parse, resolve, lower, passes, GLSL, glslang; the node "
        "library loaded once beforehand), median of " + std::to_string(r.repeat) + "; *pipeline*: the device's "
        "compilation of the pipeline (`vkCreateGraphicsPipelines`).\n";
  md += fmt::format("- *ms/frame*: a {}x{} sphere, {} frames, the wall time of one frame (draw, submit, wait) after the "
                    "first.\n",
                    r.size, r.size, r.frames);
  md += "- Scenes: ";
  for (size_t s = 0; s < scenes; ++s) md += fmt::format("{}*{}*: {}", s ? "; " : "", r.scenes[s].name, r.scenes[s].definition);
  md += ". *image difference*: the mean over covered pixels of the largest channel difference between the two images, "
        "relative to max(general, 0.05) (the proof is tests/corpus/SpecializationTest.cpp).\n";
  if (mx) {
    md += fmt::format("- MaterialX: the GLSL of MaterialX's `VkShaderGenerator` listed in `{}` (written by "
                      "`python3 tests/bench/materialx_compare.py --specialization`), compiled by the same glslang and "
                      "rendered in the same harness in the first scene, which is what its generator was asked for; "
                      "*to SPIR-V* is its pixel stage's glslang time (its generation time is in performance.md).\n",
                      r.materialxManifest);
  } else {
    md += "- MaterialX's shaders were not given (`--materialx`): its columns are empty.\n";
  }

  md += "\n## Medians\n\n| figure | median |\n|---|---:|\n";
  md += fmt::format("| instructions, specialized / general | {} |\n", number(medianInstructionRatio(r), 3));
  for (size_t s = 0; s < scenes; ++s) {
    md += fmt::format("| -O instructions, specialized / general, {} | {} |\n", r.scenes[s].name,
                      number(medianOver(r, [s](const SpecializationRow& m) {
                               return ratio(double(optimizedAt(m.specialized.shader, s)),
                                            double(optimizedAt(m.general.shader, s)));
                             }), 3));
  }
  md += fmt::format("| to SPIR-V time, specialized / general | {} |\n", number(medianOver(r, [](const SpecializationRow& m) {
                      return ratio(m.specialized.shader.toSpirvMs, m.general.shader.toSpirvMs);
                    }), 3));
  for (size_t s = 0; s < scenes; ++s) {
    md += fmt::format("| pipeline time, specialized / general, {} | {} |\n", r.scenes[s].name,
                      number(medianOver(r, [s](const SpecializationRow& m) {
                               return ratio(m.specialized.scenes.at(s).pipelineMs, m.general.scenes.at(s).pipelineMs);
                             }), 3));
    md += fmt::format("| frame time, specialized / general, {} | {} |\n", r.scenes[s].name,
                      number(medianFrameRatio(r, s), 3));
  }
  if (mx) {
    auto against = [&](auto figure) {
      return number(medianOver(r, [&](const SpecializationRow& m) {
                      return m.materialx ? figure(m.specialized, *m.materialx) : NAN;
                    }), 3);
    };
    md += fmt::format("| -O instructions, specialized / MaterialX, {} | {} |\n", r.scenes[0].name,
                      against([](const VariantFigures& a, const VariantFigures& b) {
                        return ratio(double(optimizedAt(a.shader, 0)), double(optimizedAt(b.shader, 0)));
                      }));
    md += fmt::format("| pipeline time, specialized / MaterialX, {} | {} |\n", r.scenes[0].name,
                      against([](const VariantFigures& a, const VariantFigures& b) {
                        return ratio(a.scenes.at(0).pipelineMs, b.scenes.at(0).pipelineMs);
                      }));
    md += fmt::format("| frame time, specialized / MaterialX, {} | {} |\n", r.scenes[0].name,
                      against([](const VariantFigures& a, const VariantFigures& b) {
                        return ratio(a.scenes.at(0).msPerFrame, b.scenes.at(0).msPerFrame);
                      }));
    md += fmt::format("| frame time, general / MaterialX, {} | {} |\n", r.scenes[0].name,
                      number(medianOver(r, [](const SpecializationRow& m) {
                               return m.materialx ? ratio(m.general.scenes.at(0).msPerFrame,
                                                          m.materialx->scenes.at(0).msPerFrame)
                                                  : NAN;
                             }), 3));
  }

  md += "\n## Targets\n\nThe instruction targets on each count: as compiled (the module holds every scene's code), and "
        "after -O with each scene's constants fixed (what that scene's pipeline compiles).\n\n"
        "| target | count or scene | measured | |\n|---|---|---:|---|\n";
  {
    // The counts: as compiled, then -O per scene.
    std::vector<std::pair<std::string, std::function<double(const SpecializationRow&)>>> counts;
    counts.emplace_back("as compiled", [](const SpecializationRow& m) {
      return ratio(double(m.specialized.shader.instructions), double(m.general.shader.instructions));
    });
    for (size_t s = 0; s < scenes; ++s) {
      counts.emplace_back("-O, " + r.scenes[s].name, [s](const SpecializationRow& m) {
        return ratio(double(optimizedAt(m.specialized.shader, s)), double(optimizedAt(m.general.shader, s)));
      });
    }
    for (const auto& [count, figure] : counts) {
      const double median = medianOver(r, figure);
      md += fmt::format("| median instructions, specialized / general, at most {} | {} | {} | {} |\n",
                        kTargetInstructionRatio, count, number(median, 3), verdict(median, kTargetInstructionRatio));
    }
    for (const char* file : kDiffuseMaterials) {
      const SpecializationRow* m = rowOf(r, file);
      for (const auto& [count, figure] : counts) {
        const double v = m ? figure(*m) : NAN;
        md += fmt::format("| {} (diffuse, under a rough specular): instructions, specialized / general, at most {} | {} | "
                          "{} | {} |\n",
                          file, kTargetDiffuseRatio, count, number(v, 3), verdict(v, kTargetDiffuseRatio));
      }
    }
  }
  {
    const SpecializationRow* m = rowOf(r, kMaterialXFrameTarget);
    const double v = m && m->materialx ? ratio(m->specialized.scenes.at(0).msPerFrame, m->materialx->scenes.at(0).msPerFrame)
                                       : NAN;
    md += fmt::format("| {}: frame time, specialized / MaterialX, at most {} | {} | {} | {} |\n", kMaterialXFrameTarget,
                      kTargetMaterialXFrameRatio, scenes ? r.scenes[0].name : "", number(v, 3),
                      verdict(v, kTargetMaterialXFrameRatio));
  }

  md += "\n## Shader size and compile time\n\n";
  md += "| material | model | instructions general | specialized | ratio |";
  for (size_t s = 0; s < scenes; ++s) md += fmt::format(" -O general / specialized, {} | ratio |", r.scenes[s].name);
  md += " to SPIR-V ms general | specialized |";
  if (mx) md += " MaterialX instructions | -O | MaterialX glslang ms |";
  md += "\n|---|---|---:|---:|---:|";
  for (size_t s = 0; s < scenes; ++s) md += "---:|---:|";
  md += "---:|---:|";
  if (mx) md += "---:|---:|---:|";
  md += "\n";
  for (const SpecializationRow& m : r.materials) {
    const ShaderFigures &g = m.general.shader, &p = m.specialized.shader;
    md += fmt::format("| {} ({}) | {} | {} | {} | {} |", m.name, m.source, m.model, g.instructions, p.instructions,
                      number(ratio(double(p.instructions), double(g.instructions)), 2));
    for (size_t s = 0; s < scenes; ++s) {
      md += fmt::format(" {} / {} | {} |", optimizedAt(g, s), optimizedAt(p, s),
                        number(ratio(double(optimizedAt(p, s)), double(optimizedAt(g, s))), 2));
    }
    md += fmt::format(" {} | {} |", number(g.toSpirvMs), number(p.toSpirvMs));
    if (mx) {
      if (m.materialx) {
        md += fmt::format(" {} | {} | {} |", m.materialx->shader.instructions, optimizedAt(m.materialx->shader, 0),
                          number(m.materialx->shader.toSpirvMs));
      } else {
        md += " - | - | - |";
      }
    }
    md += "\n";
  }

  for (size_t s = 0; s < scenes; ++s) {
    md += fmt::format("\n## Frame and pipeline time: {}\n\n", r.scenes[s].name);
    md += "| material | ms/frame general | specialized | ratio | pipeline ms general | specialized | ratio | image "
          "difference |";
    const bool withMx = mx && s == 0;
    if (withMx) md += " MaterialX ms/frame | pipeline ms | specialized / MaterialX frame |";
    md += "\n|---|---:|---:|---:|---:|---:|---:|---:|";
    if (withMx) md += "---:|---:|---:|";
    md += "\n";
    for (const SpecializationRow& m : r.materials) {
      const SceneFigures &g = m.general.scenes.at(s), &p = m.specialized.scenes.at(s);
      md += fmt::format("| {} ({}) | {} | {} | {} | {} | {} | {} | {} |", m.name, m.source, number(g.msPerFrame),
                        number(p.msPerFrame), number(ratio(p.msPerFrame, g.msPerFrame), 2), number(g.pipelineMs, 0),
                        number(p.pipelineMs, 0), number(ratio(p.pipelineMs, g.pipelineMs), 2),
                        s < m.imageDifference.size() ? fmt::format("{:.1e}", m.imageDifference[s]) : "-");
      if (withMx) {
        if (m.materialx) {
          const SceneFigures& x = m.materialx->scenes.at(0);
          md += fmt::format(" {} | {} | {} |", number(x.msPerFrame), number(x.pipelineMs, 0),
                            number(ratio(p.msPerFrame, x.msPerFrame), 2));
        } else {
          md += " - | - | - |";
        }
      }
      md += "\n";
    }
  }
  return md;
}

std::string specializationCsv(const SpecializationReport& r) {
  std::string csv =
      "material,source,model,shader,scene,instructions,optimized,to_spirv_ms,ms_per_frame,pipeline_ms,image_difference\n";
  for (const SpecializationRow& m : r.materials) {
    auto rows = [&](const char* shader, const VariantFigures& v, bool difference) {
      for (size_t s = 0; s < r.scenes.size() && s < v.scenes.size(); ++s) {
        csv += fmt::format("{},{},{},{},{},{},{},{:.3f},{:.3f},{:.1f},{}\n", csvText(m.name), csvText(m.source),
                           csvText(m.model), shader, csvText(r.scenes[s].name), v.shader.instructions,
                           optimizedAt(v.shader, s), v.shader.toSpirvMs, v.scenes[s].msPerFrame, v.scenes[s].pipelineMs,
                           difference && s < m.imageDifference.size() ? fmt::format("{:.3e}", m.imageDifference[s]) : "");
      }
    };
    rows("general", m.general, false);
    rows("specialized", m.specialized, true);
    if (m.materialx) rows("materialx", *m.materialx, false);
  }
  return csv;
}

}  // namespace mxc::cli
