// libFuzzer program for the XML parser (scripts/fuzz builds and runs it).
#include "FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  mxc::fuzz::parseXml(data, size);
  return 0;
}
