#pragma once
// `mxc render` from tests, its image read back: for the tests of the command and of scenes.

#include <string>
#include <variant>

#include <gtest/gtest.h>

#include "runtime/ImageIO.h"
#include "support/CommandSupport.h"

namespace mxc::test {

/// `mxc render ARGUMENTS -o a temporary .exr` (after `shell`, as mxc() runs it), the exit code
/// expected, the image read back (empty when none was written).
inline rt::RgbaImage renderCommand(const std::string& arguments, int expectedCode = 0, const std::string& shell = {}) {
  const fs::path out = writeTemp("render_command.exr", "");
  fs::remove(out);
  CommandRun r = mxc("render " + arguments + " -o " + out.string(), shell);
  EXPECT_EQ(r.exitCode, expectedCode) << r.err;
  auto image = rt::readImage(out);
  fs::remove(out);
  return std::holds_alternative<rt::RgbaImage>(image) ? std::get<rt::RgbaImage>(image) : rt::RgbaImage{};
}

}  // namespace mxc::test
