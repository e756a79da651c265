// The camera, lights and environment of the raster renderer (binding 1, filled by
// runtime/Renderer.cpp), shared by its vertex and fragment stages.

#include "generated/mxc_view_block.glsl"
