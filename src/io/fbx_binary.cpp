#include "io/fbx_binary.h"

#include <bit>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace gyre::io::fbx {

static_assert(std::endian::native == std::endian::little, "binary FBX is little-endian; values are copied as they are");

namespace {

constexpr std::string_view kMagic{"Kaydara FBX Binary  \0\x1a\0", 23};
constexpr std::size_t kNullRecordSize = 13; // three uint32 and a name length, all zero

// The codes of the FBX SDK's footer and the FileId and CreationTime they go with.
constexpr std::string_view kFileId{"\x28\xb3\x2a\xeb\xb6\x24\xcc\xc2\xbf\xc8\xb0\x2a\xa9\x2b\xfc\xf1", 16};
constexpr std::string_view kCreationTime{"1970-01-01 10:00:00:000"};
constexpr std::string_view kFooterCode{"\xfa\xbc\xab\x09\xd0\xc8\xd4\x66\xb1\x76\xfb\x83\x1c\xf7\x26\x7e", 16};
constexpr std::string_view kFooterTail{"\xf8\x5a\x8c\x6a\xde\xf5\xd9\x7e\xec\xe9\x0c\xe3\x75\x8f\x29\x0b", 16};
constexpr std::size_t kFooterZeros = 120;

template <class T>
void append(std::string& out, T value)
{
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    out.append(bytes, sizeof(T));
}

std::uint32_t checkedCount(std::size_t count)
{
    if (count > std::numeric_limits<std::uint32_t>::max())
        throw std::length_error("an FBX property holds more than 2^32 - 1 bytes");
    return static_cast<std::uint32_t>(count);
}

bool hasNestedList(const Node& node) { return !node.children().empty() || node.propertyCount() == 0; }

// The bytes of the node and everything under it.
std::size_t encodedSize(const Node& node)
{
    std::size_t size = 3 * sizeof(std::uint32_t) + 1 + node.name().size() + node.properties().size();
    for (const Node& child : node.children())
        size += encodedSize(child);
    if (hasNestedList(node))
        size += kNullRecordSize;
    return size;
}

void writeNode(const Node& node, std::string& out)
{
    append<std::uint32_t>(out, static_cast<std::uint32_t>(out.size() + encodedSize(node)));
    append<std::uint32_t>(out, node.propertyCount());
    append<std::uint32_t>(out, static_cast<std::uint32_t>(node.properties().size()));
    append<std::uint8_t>(out, static_cast<std::uint8_t>(node.name().size()));
    out += node.name();
    out += node.properties();
    for (const Node& child : node.children())
        writeNode(child, out);
    if (hasNestedList(node))
        out.append(kNullRecordSize, '\0');
}

} // namespace

Node::Node(std::string_view name)
    : name_(name)
{
    if (name.size() > std::numeric_limits<std::uint8_t>::max())
        throw std::length_error("an FBX node name is longer than 255 bytes");
}

template <class T>
Node& Node::addValue(char type, T value)
{
    properties_ += type;
    append(properties_, value);
    ++propertyCount_;
    return *this;
}

Node& Node::addInt16(std::int16_t value) { return addValue('Y', value); }
Node& Node::addBool(bool value) { return addValue('C', static_cast<std::uint8_t>(value ? 1 : 0)); }
Node& Node::addInt32(std::int32_t value) { return addValue('I', value); }
Node& Node::addFloat(float value) { return addValue('F', value); }
Node& Node::addDouble(double value) { return addValue('D', value); }
Node& Node::addInt64(std::int64_t value) { return addValue('L', value); }

Node& Node::addBytes(char type, std::string_view bytes)
{
    properties_ += type;
    append(properties_, checkedCount(bytes.size()));
    properties_ += bytes;
    ++propertyCount_;
    return *this;
}

Node& Node::addString(std::string_view value) { return addBytes('S', value); }
Node& Node::addRaw(std::string_view bytes) { return addBytes('R', bytes); }

// An array: its type, count, encoding 0 (raw), byte length and elements.
template <class T>
Node& Node::addArrayOf(char type, std::span<const T> values)
{
    const std::uint32_t bytes = checkedCount(values.size_bytes());
    properties_ += type;
    append(properties_, static_cast<std::uint32_t>(values.size()));
    append(properties_, std::uint32_t{0});
    append(properties_, bytes);
    if (bytes > 0) // an empty span's data() may be null
        properties_.append(reinterpret_cast<const char*>(values.data()), bytes);
    ++propertyCount_;
    return *this;
}

Node& Node::addArray(std::span<const std::int32_t> values) { return addArrayOf('i', values); }
Node& Node::addArray(std::span<const float> values) { return addArrayOf('f', values); }
Node& Node::addArray(std::span<const double> values) { return addArrayOf('d', values); }
Node& Node::addArray(std::span<const std::int64_t> values) { return addArrayOf('l', values); }

Node& Node::addBoolArray(const std::vector<bool>& values)
{
    const std::vector<std::uint8_t> bytes(values.begin(), values.end());
    return addArrayOf('b', std::span<const std::uint8_t>(bytes));
}

Node& Node::addChild(std::string_view name) { return children_.emplace_back(name); }

std::string encodeFile(const Node& root)
{
    std::size_t size = kMagic.size() + sizeof(std::uint32_t) + kNullRecordSize;
    for (const Node& node : root.children())
        size += encodedSize(node);
    // Every end offset must fit in 32 bits; the footer adds at most 180 bytes after the last one.
    if (size > std::numeric_limits<std::uint32_t>::max())
        throw std::length_error("the FBX file would be larger than 4 GiB, the most FBX 7.4 can address");

    std::string out;
    out.reserve(size + 200);
    out += kMagic;
    append(out, kVersion);
    for (const Node& node : root.children())
        writeNode(node, out);
    out.append(kNullRecordSize, '\0');

    out += kFooterCode;
    out.append(4, '\0');
    const std::size_t padding = 16 - out.size() % 16; // 16 when already aligned
    out.append(padding, '\0');
    append(out, kVersion);
    out.append(kFooterZeros, '\0');
    out += kFooterTail;
    return out;
}

FileIdentity fileIdentity() { return {kFileId, kCreationTime}; }

} // namespace gyre::io::fbx
