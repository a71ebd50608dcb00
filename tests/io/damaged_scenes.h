#pragma once
// Collada files that Debian's Assimp 5.2.5 does not survive, for the tests of the scene worker. A
// float_array whose count is "-0" makes the reader crash with SIGSEGV; one that announces 1.5 billion
// floats makes it reserve 6 GB for them.

#include <QByteArray>

namespace gyre::test {

inline QByteArray colladaWithFloatCount(const char* count)
{
    return QByteArray("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n"
                      "<COLLADA xmlns=\"http://www.collada.org/2005/11/COLLADASchema\" version=\"1.4.1\">\n"
                      "<library_geometries><geometry id=\"g\"><mesh>\n"
                      "<source id=\"p\"><float_array id=\"pa\" count=\"") +
           count +
           "\">0 0 0 1 0 0 0 1 0</float_array>\n"
           "<technique_common><accessor source=\"#pa\" count=\"3\" stride=\"3\">\n"
           "<param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/><param name=\"Z\" type=\"float\"/>\n"
           "</accessor></technique_common></source>\n"
           "<vertices id=\"v\"><input semantic=\"POSITION\" source=\"#p\"/></vertices>\n"
           "<triangles count=\"1\"><input semantic=\"VERTEX\" source=\"#v\" offset=\"0\"/><p>0 1 2</p></triangles>\n"
           "</mesh></geometry></library_geometries>\n"
           "<library_visual_scenes><visual_scene id=\"s\"><node id=\"n\"><instance_geometry url=\"#g\"/></node>\n"
           "</visual_scene></library_visual_scenes>\n"
           "<scene><instance_visual_scene url=\"#s\"/></scene>\n"
           "</COLLADA>\n";
}

inline QByteArray crashingCollada() { return colladaWithFloatCount("-0"); }

// How the worker ends on crashingCollada(): by the segmentation fault, or where AddressSanitizer
// reports it first, by the abort() that ends its report (io/scene_worker.cpp).
#if defined(__SANITIZE_ADDRESS__)
inline constexpr char kCrashSignal[] = "6, SIGABRT)";
#else
inline constexpr char kCrashSignal[] = "11, SIGSEGV)";
#endif
inline QByteArray hugeCollada() { return colladaWithFloatCount("1500000000"); }

} // namespace gyre::test
