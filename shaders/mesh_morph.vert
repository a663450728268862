#version 450
// Posed mesh with morph targets (MORPH); the code is shaders/mesh_vertex.glsl.
#extension GL_GOOGLE_include_directive : require
#define MORPH 1
#include "mesh_vertex.glsl"
