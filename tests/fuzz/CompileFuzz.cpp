// libFuzzer program for parse + resolve + lower + passes + GLSL (scripts/fuzz builds and runs it).
#include "FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  mxc::fuzz::compileDocument(data, size);
  return 0;
}
