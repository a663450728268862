# signstim_renderer_gltf_tests (glTF side): loader, broken input, animation, output, video.
