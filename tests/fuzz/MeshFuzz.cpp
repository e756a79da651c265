// libFuzzer program for mesh files (OBJ, glTF and binary glTF by their first bytes); scripts/fuzz builds and runs it.
#include "FuzzTargets.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  mxc::fuzz::loadMeshFile(data, size);
  return 0;
}
