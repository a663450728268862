#version 450
// Posed mesh without morph targets; the code is shaders/mesh_vertex.glsl.
#extension GL_GOOGLE_include_directive : require
#include "mesh_vertex.glsl"
