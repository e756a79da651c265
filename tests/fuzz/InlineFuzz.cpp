// libFuzzer program for inline source implementations (the bytes are a node's sourcecode); scripts/fuzz builds and runs it.
#include "FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  mxc::fuzz::compileInlineSource(data, size);
  return 0;
}
