// The binary FBX encoder (io/fbx_binary.h) against files written out byte by byte here, from the
// format as Blender's and Assimp's readers take it: the header, node records with their absolute end
// offsets, the nested lists and their 13-byte null records, every property type, and the footer.

#include "io/fbx_binary.h"

#include <QObject>
#include <QTest>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

using gyre::io::fbx::Node;

namespace {

using namespace gyre::io;

// Little-endian bytes of a value, written out independently of the encoder.
std::string le32(std::uint32_t v)
{
    return {static_cast<char>(v & 0xff), static_cast<char>((v >> 8) & 0xff), static_cast<char>((v >> 16) & 0xff),
            static_cast<char>((v >> 24) & 0xff)};
}

std::string le64(std::uint64_t v)
{
    return le32(static_cast<std::uint32_t>(v)) + le32(static_cast<std::uint32_t>(v >> 32));
}

std::string zeros(std::size_t n) { return std::string(n, '\0'); }

const std::string kHeader = std::string("Kaydara FBX Binary  \0\x1a\0", 23) + le32(7400);
const std::string kFooterCode("\xfa\xbc\xab\x09\xd0\xc8\xd4\x66\xb1\x76\xfb\x83\x1c\xf7\x26\x7e", 16);
const std::string kFooterTail("\xf8\x5a\x8c\x6a\xde\xf5\xd9\x7e\xec\xe9\x0c\xe3\x75\x8f\x29\x0b", 16);

// The footer after the top-level null record; `padding` brings its code and 4 zeros to a multiple
// of 16 bytes (each caller works it out from where that record ends).
std::string footer(std::size_t padding)
{
    return kFooterCode + zeros(4) + zeros(padding) + le32(7400) + zeros(120) + kFooterTail;
}

QByteArray bytes(const std::string& s) { return QByteArray(s.data(), static_cast<qsizetype>(s.size())); }

} // namespace

class TstFbxBinary : public QObject {
    Q_OBJECT

private slots:
    void oneNodeFile();
    void nestedAndEmptyNodes();
    void footerPadsAWholeBlockWhenAligned();
    void scalarProperties();
    void stringsAndRawBytes();
    void arrays();
    void longNamesAreRefused();
};

// A top-level node N with one int32 property: 27 bytes of header, the node from 27 to 46, the
// top-level null record to 59, then the footer (79 after its code and 4 zeros: 1 byte of padding).
void TstFbxBinary::oneNodeFile()
{
    Node root("");
    root.addChild("N").addInt32(1);
    const std::string expected = kHeader + le32(46) + le32(1) + le32(5) + "\x01N" + "I" + le32(1) + zeros(13) + footer(1);
    const std::string file = gyre::io::fbx::encodeFile(root);
    QCOMPARE(bytes(file), bytes(expected));
    QCOMPARE(file.size(), std::size_t{220});
}

// P { Q {} ; R: 5 }: Q has no properties, so a null record closes its (empty) nested list; R has a
// property and no children, so it has none; P's children end with a null record.
void TstFbxBinary::nestedAndEmptyNodes()
{
    Node root("");
    Node& p = root.addChild("P");
    p.addChild("Q");
    p.addChild("R").addInt64(5);
    std::string expected = kHeader;
    expected += le32(104) + le32(0) + le32(0) + "\x01P";               // P: 27 to 104
    expected += le32(68) + le32(0) + le32(0) + "\x01Q" + zeros(13);    // Q: 41 to 68
    expected += le32(91) + le32(1) + le32(9) + "\x01R" + "L" + le64(5); // R: 68 to 91
    expected += zeros(13);                                              // P's null record, to 104
    expected += zeros(13) + footer(7);                           // the top level's
    QCOMPARE(bytes(gyre::io::fbx::encodeFile(root)), bytes(expected));
    QCOMPARE(p.children().size(), std::size_t{2});
    QCOMPARE(p.children()[0].name(), std::string("Q"));
}

// When the footer's code and zeros end on a multiple of 16, the padding is a whole 16 bytes.
void TstFbxBinary::footerPadsAWholeBlockWhenAligned()
{
    Node root("");
    root.addChild("ABCDEFGHIJ"); // 27 to 63 with its null record; the top level's ends at 76, 76 + 20 = 96
    const std::string expected = kHeader + le32(63) + le32(0) + le32(0) + "\x0a" "ABCDEFGHIJ" + zeros(13) + zeros(13) +
                                 footer(16);
    QCOMPARE(bytes(gyre::io::fbx::encodeFile(root)), bytes(expected));
}

void TstFbxBinary::scalarProperties()
{
    Node node("S");
    node.addInt16(-2).addBool(true).addBool(false).addInt32(-7);
    node.addFloat(1.5f).addDouble(-0.25).addInt64(std::int64_t{1} << 40);
    std::string expected = std::string("Y\xfe\xff", 3) + "C\x01" + std::string("C\0", 2);
    expected += "I" + le32(static_cast<std::uint32_t>(-7));
    expected += "F" + le32(0x3fc00000);          // 1.5f
    expected += "D" + le64(0xbfd0000000000000);  // -0.25
    expected += "L" + le64(std::uint64_t{1} << 40);
    QCOMPARE(bytes(node.properties()), bytes(expected));
    QCOMPARE(node.propertyCount(), 7u);
}

// Strings keep every byte, NUL included (binary FBX writes "Name\0\1Class"), with no terminator.
void TstFbxBinary::stringsAndRawBytes()
{
    Node node("T");
    node.addString(std::string("Würfel 2\0\1Model", 16)).addRaw(std::string("\0\xff", 2)).addString("");
    const std::string expected = "S" + le32(16) + std::string("Würfel 2\0\1Model", 16) + "R" + le32(2) +
                                 std::string("\0\xff", 2) + "S" + le32(0);
    QCOMPARE(bytes(node.properties()), bytes(expected));
    QCOMPARE(node.propertyCount(), 3u);
}

// Arrays: count, encoding 0 (raw), byte length, the elements.
void TstFbxBinary::arrays()
{
    const std::int32_t ints[] = {1, -1};
    const float floats[] = {2.5f};
    const std::int64_t longs[] = {3};
    Node node("A");
    node.addArray(std::span<const std::int32_t>(ints))
        .addArray(std::span<const float>(floats))
        .addArray(std::span<const double>())
        .addArray(std::span<const std::int64_t>(longs))
        .addBoolArray({true, false, true});
    std::string expected = "i" + le32(2) + le32(0) + le32(8) + le32(1) + le32(0xffffffff);
    expected += "f" + le32(1) + le32(0) + le32(4) + le32(0x40200000); // 2.5f
    expected += "d" + le32(0) + le32(0) + le32(0);
    expected += "l" + le32(1) + le32(0) + le32(8) + le64(3);
    expected += "b" + le32(3) + le32(0) + le32(3) + "\x01" + std::string("\0", 1) + "\x01";
    QCOMPARE(bytes(node.properties()), bytes(expected));
    QCOMPARE(node.propertyCount(), 5u);
}

void TstFbxBinary::longNamesAreRefused()
{
    QVERIFY_THROWS_EXCEPTION(std::length_error, Node(std::string(256, 'x')));
    QCOMPARE(Node(std::string(255, 'x')).name().size(), std::size_t{255});
}

QTEST_GUILESS_MAIN(TstFbxBinary)
#include "tst_fbx_binary.moc"
