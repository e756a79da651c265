// libFuzzer program for scene files (JSON read and checked as mxc render reads them); scripts/fuzz builds and runs it.
#include "FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  mxc::fuzz::readSceneJson(data, size);
  return 0;
}
