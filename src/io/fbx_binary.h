#pragma once
// Binary FBX 7.4 (version 7400), the node-record encoding that Blender's and Assimp's FBX readers
// read. A file is a tree of nodes, each a name with typed properties and child nodes:
//
//   file    = "Kaydara FBX Binary  \0\x1a\0" (23 bytes), uint32 version, node*, null record, footer
//   node    = uint32 endOffset (absolute, of the byte after the node), uint32 propertyCount,
//             uint32 propertyListLength (bytes), uint8 nameLength, name, property*,
//             [node* null record]   (the nested list: present when the node has children or no
//                                    properties, as the FBX SDK writes it)
//   null record = 13 zero bytes (an endOffset of 0 ends a list)
//   property = one type byte, then
//     Y int16, C bool (1 byte), I int32, F float32, D float64, L int64   (little-endian)
//     S string, R raw bytes: uint32 length, the bytes (no terminator)
//     i int32[], f float32[], d float64[], l int64[], b bool[]: uint32 count, uint32 encoding (0:
//       raw; 1 would be zlib), uint32 byte length, the elements
//   footer  = a 16-byte code, 4 zero bytes, zero padding to a multiple of 16 (16 bytes when already
//             aligned), uint32 version, 120 zero bytes, a fixed 16-byte code.
// FBX 7.5 widens the three node words to 64 bits; 7.4 limits a file to 4 GiB.
//
// The format is described by what its readers expect: Blender's io_scene_fbx (parse_fbx.py and
// encode_bin.py) and Assimp's FBXBinaryTokenizer. The footer's first code goes with the top-level
// FileId and CreationTime that fileIdentity() gives; readers do not check either.

#include <cstdint>
#include <deque>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace gyre::io::fbx {

inline constexpr std::uint32_t kVersion = 7400;

class Node {
public:
    explicit Node(std::string_view name); // at most 255 bytes, else std::length_error

    Node& addInt16(std::int16_t value);   // Y
    Node& addBool(bool value);            // C
    Node& addInt32(std::int32_t value);   // I
    Node& addFloat(float value);          // F
    Node& addDouble(double value);        // D
    Node& addInt64(std::int64_t value);   // L
    Node& addString(std::string_view value); // S
    Node& addRaw(std::string_view bytes); // R
    Node& addArray(std::span<const std::int32_t> values); // i
    Node& addArray(std::span<const float> values);        // f
    Node& addArray(std::span<const double> values);       // d
    Node& addArray(std::span<const std::int64_t> values); // l
    Node& addBoolArray(const std::vector<bool>& values);  // b

    // A new last child. References to children stay valid as more are added.
    Node& addChild(std::string_view name);

    const std::string& name() const { return name_; }
    std::uint32_t propertyCount() const { return propertyCount_; }
    const std::string& properties() const { return properties_; } // the encoded property list
    const std::deque<Node>& children() const { return children_; }

private:
    template <class T>
    Node& addValue(char type, T value);
    Node& addBytes(char type, std::string_view bytes);
    template <class T>
    Node& addArrayOf(char type, std::span<const T> values);

    std::string name_;
    std::uint32_t propertyCount_ = 0;
    std::string properties_;
    std::deque<Node> children_;
};

// The bytes of a whole file whose top-level nodes are `root`'s children (root's own name and
// properties are not written). Throws std::length_error when the file would pass 4 GiB.
std::string encodeFile(const Node& root);

// The FileId and CreationTime that go with the footer encodeFile writes.
struct FileIdentity {
    std::string_view fileId;       // 16 bytes, written as R
    std::string_view creationTime; // written as S
};
FileIdentity fileIdentity();

} // namespace gyre::io::fbx
