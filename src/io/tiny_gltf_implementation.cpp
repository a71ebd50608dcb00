// TinyGLTF's code, compiled once into gyre_io (its header holds the implementation behind
// TINYGLTF_IMPLEMENTATION). Debian's libtinygltf.so is not used: objects made by the header in Gyre's
// code and freed by that library's build did not agree (a crash in ~TinyGLTF), and compiling it here
// keeps TinyGLTF a header-only build dependency, with no runtime package. Images are never decoded
// (TINYGLTF_NO_STB_IMAGE, set for the target): Gyre keeps no materials.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
