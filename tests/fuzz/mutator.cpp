#include "mutator.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>

#include <array>
#include <cstring>
#include <limits>
#include <functional>
#include <optional>

namespace gyre::fuzz {

namespace {

// Numbers at the edges of what text, doubles and integers hold, and counts that are wrong.
constexpr std::array<const char*, 22> kExtremeNumbers{
    "0",    "-0",   "1e308", "-1e308", "1e-320", "4.9e-324", "nan", "-nan", "inf", "-inf", "1e999",
    "NaN",  "-1",   "-2147483648", "2147483647", "4294967296", "9223372036854775807",
    "18446744073709551616", "99999999999999999999999999999", "16", "17", "0x10"};

// A JSON value edited: a different type, or a value the format bounds.
const std::array<QJsonValue, 12> kReplacementValues{
    QJsonValue(), QJsonValue(true), QJsonValue(QStringLiteral("text")), QJsonValue(QJsonObject()),
    QJsonValue(QJsonArray()), QJsonValue(0), QJsonValue(-1), QJsonValue(1e308), QJsonValue(4294967297.0),
    QJsonValue(2147483647), QJsonValue(QStringLiteral("////")), QJsonValue(QJsonArray{1, 2, 3})};

// Whether a value takes a few bytes of text at most, as a number or [w, x, y, z] does.
bool isSmall(const QJsonValue& value)
{
    if (value.isObject() || value.isArray()) {
        const QJsonDocument document = value.isObject() ? QJsonDocument(value.toObject()) : QJsonDocument(value.toArray());
        return document.toJson(QJsonDocument::Compact).size() <= 64;
    }
    return !value.isString() || value.toString().size() <= 16;
}

// A version 3 project starts with this, its version (uint32) and its header's length (uint64).
const QByteArray kBinaryProject = QByteArrayLiteral("gyre-project");
constexpr qsizetype kPreambleBytes = 24;

// Values a block may be given in place of a float64: not finite, beyond every bound, denormal,
// negative zero; and, read as a uint64 count or a flag byte, huge or neither 0 nor 1.
constexpr std::array<double, 9> kExtremeDoubles{std::numeric_limits<double>::quiet_NaN(),
                                                std::numeric_limits<double>::infinity(),
                                                -std::numeric_limits<double>::infinity(),
                                                1e308, 4.9e-324, -0.0, 2.0, 1.0000001e6, 1e-3};

enum class JsonEdit { Remove, Replace, HugeArray, DuplicateElement, HugeBase64 };
constexpr int kJsonEdits = 5;
constexpr qsizetype kMaxEditedBytes = qsizetype{1} << 20;

// Visits the values of a document in order, and edits the one numbered `target`. Returns the edited
// value, or nothing where the edit removes it.
class JsonEditor {
public:
    JsonEditor(std::size_t target, std::function<std::optional<QJsonValue>(const QJsonValue&)> edit)
        : target_(target), edit_(std::move(edit))
    {
    }

    std::optional<QJsonValue> visit(const QJsonValue& value)
    {
        if (count_++ == target_)
            return edit_(value);
        if (value.isObject()) {
            QJsonObject object = value.toObject();
            for (const QString& key : object.keys()) {
                if (const std::optional<QJsonValue> edited = visit(object.value(key)))
                    object[key] = *edited;
                else
                    object.remove(key);
            }
            return object;
        }
        if (value.isArray()) {
            QJsonArray array;
            for (const QJsonValue& element : value.toArray())
                if (const std::optional<QJsonValue> edited = visit(element))
                    array.append(*edited);
            return array;
        }
        return value;
    }

    std::size_t count() const { return count_; }

private:
    std::size_t target_;
    std::function<std::optional<QJsonValue>(const QJsonValue&)> edit_;
    std::size_t count_ = 0;
};

} // namespace

std::size_t Mutator::below(std::size_t count)
{
    return count == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, count - 1)(engine_);
}

QByteArray Mutator::mutate(const QByteArray& bytes, bool json)
{
    QByteArray mutant = bytes;
    const std::size_t edits = 1 + below(3);
    for (std::size_t i = 0; i < edits; ++i) {
        if (json && mutant.startsWith(kBinaryProject) && below(2) == 0) {
            editBinaryProject(mutant);
            continue;
        }
        switch (below(json ? 8 : 6)) {
        case 0: flipBytes(mutant); break;
        case 1: insertBytes(mutant); break;
        case 2: deleteBytes(mutant); break;
        case 3: duplicateLine(mutant); break;
        case 4: truncate(mutant); break;
        case 5: replaceNumber(mutant); break;
        default: editJson(mutant); break; // twice as likely for a project: its structure is most of it
        }
    }
    return mutant;
}

void Mutator::flipBytes(QByteArray& bytes)
{
    for (std::size_t n = 1 + below(4); n > 0 && !bytes.isEmpty(); --n)
        bytes[static_cast<qsizetype>(below(static_cast<std::size_t>(bytes.size())))] ^=
            static_cast<char>(1 << below(8));
}

void Mutator::insertBytes(QByteArray& bytes)
{
    // Random bytes, or the characters that mean something to the formats.
    static const QByteArray kMeaningful = QByteArrayLiteral(",\n\r#\"{}[]:-.e \t\0\xEF\xBB\xBF");
    QByteArray inserted;
    for (std::size_t n = 1 + below(8); n > 0; --n)
        inserted += below(2) == 0 ? static_cast<char>(below(256))
                                  : kMeaningful[static_cast<qsizetype>(below(static_cast<std::size_t>(kMeaningful.size())))];
    bytes.insert(static_cast<qsizetype>(below(static_cast<std::size_t>(bytes.size()) + 1)), inserted);
}

void Mutator::deleteBytes(QByteArray& bytes)
{
    if (bytes.isEmpty())
        return;
    const auto at = static_cast<qsizetype>(below(static_cast<std::size_t>(bytes.size())));
    bytes.remove(at, static_cast<qsizetype>(1 + below(16)));
}

void Mutator::duplicateLine(QByteArray& bytes)
{
    QList<QByteArray> lines = bytes.split('\n');
    const std::size_t line = below(static_cast<std::size_t>(lines.size()));
    const QByteArray copy = lines[static_cast<qsizetype>(line)];
    for (std::size_t n = 1 + below(3); n > 0; --n)
        lines.insert(static_cast<qsizetype>(below(static_cast<std::size_t>(lines.size()) + 1)), copy);
    bytes = lines.join('\n');
}

void Mutator::truncate(QByteArray& bytes)
{
    if (below(2) == 0) {
        bytes.truncate(static_cast<qsizetype>(below(static_cast<std::size_t>(bytes.size()) + 1)));
        return;
    }
    // A line cut short where it is.
    QList<QByteArray> lines = bytes.split('\n');
    QByteArray& line = lines[static_cast<qsizetype>(below(static_cast<std::size_t>(lines.size())))];
    line.truncate(static_cast<qsizetype>(below(static_cast<std::size_t>(line.size()) + 1)));
    bytes = lines.join('\n');
}

void Mutator::replaceNumber(QByteArray& bytes)
{
    static const QRegularExpression kNumber(QStringLiteral("-?[0-9]+(\\.[0-9]+)?([eE][-+]?[0-9]+)?"));
    const QString text = QString::fromLatin1(bytes);
    std::vector<QRegularExpressionMatch> numbers;
    for (QRegularExpressionMatch match : kNumber.globalMatch(text))
        numbers.push_back(match);
    if (numbers.empty())
        return;
    const QRegularExpressionMatch& chosen = numbers[below(numbers.size())];
    bytes.replace(chosen.capturedStart(), chosen.capturedLength(), kExtremeNumbers[below(kExtremeNumbers.size())]);
}

void Mutator::editJson(QByteArray& bytes)
{
    const QJsonDocument document = QJsonDocument::fromJson(bytes);
    if (!document.isObject())
        return;
    JsonEditor counter(std::size_t(-1), {});
    counter.visit(document.object());
    const auto edit = static_cast<JsonEdit>(below(kJsonEdits));
    JsonEditor editor(1 + below(counter.count() - 1), [&](const QJsonValue& value) -> std::optional<QJsonValue> {
        switch (edit) {
        case JsonEdit::Remove:
            return std::nullopt;
        case JsonEdit::Replace:
            return kReplacementValues[below(kReplacementValues.size())];
        case JsonEdit::HugeArray: {
            // Many elements in few bytes: a reader that reserves by count, or does work per element,
            // shows it here. Only small elements are repeated, so that the file stays small.
            const QJsonValue first = value.isArray() && !value.toArray().isEmpty() ? value.toArray().first() : value;
            const QJsonValue element = isSmall(first) ? first : kReplacementValues[below(kReplacementValues.size())];
            QJsonArray array;
            for (std::size_t n = below(2) == 0 ? 1000 : 100000; n > 0; --n)
                array.append(element);
            return array;
        }
        case JsonEdit::DuplicateElement: {
            if (!value.isArray() || value.toArray().isEmpty())
                return value;
            QJsonArray array = value.toArray();
            const QJsonValue element = array[static_cast<qsizetype>(below(static_cast<std::size_t>(array.size())))];
            for (std::size_t n = 1 + below(50); n > 0; --n)
                array.insert(static_cast<qsizetype>(below(static_cast<std::size_t>(array.size()) + 1)), element);
            return array;
        }
        case JsonEdit::HugeBase64:
            // Mesh data whose every index and coordinate is all ones: indices far out of range, NaN floats.
            return QString::fromLatin1(QByteArray(static_cast<qsizetype>(12 * (1 + below(4096))), '\xFF').toBase64());
        }
        return value;
    });
    const QByteArray edited = QJsonDocument(editor.visit(document.object())->toObject()).toJson(
        below(2) == 0 ? QJsonDocument::Indented : QJsonDocument::Compact);
    // A second huge array inside the first would make a file of hundreds of megabytes: slow to read
    // for its size alone, which tells nothing.
    if (edited.size() <= kMaxEditedBytes)
        bytes = edited;
}

void Mutator::editBinaryProject(QByteArray& bytes)
{
    if (bytes.size() < kPreambleBytes)
        return;
    quint64 headerBytes = 0;
    std::memcpy(&headerBytes, bytes.constData() + 16, sizeof headerBytes); // little-endian, as is the machine
    if (headerBytes > static_cast<quint64>(bytes.size() - kPreambleBytes))
        return;
    QByteArray header = bytes.mid(kPreambleBytes, static_cast<qsizetype>(headerBytes));
    QByteArray blocks = bytes.mid(kPreambleBytes + static_cast<qsizetype>(headerBytes));
    switch (below(5)) {
    case 0: // the header's counts and indices, its length kept right so that the blocks are reached
        replaceNumber(header);
        break;
    case 1:
        editJson(header);
        break;
    case 2: // a float64 of a block: a time, a quaternion's or a position's coordinate
        if (blocks.size() >= 8) {
            const double value = kExtremeDoubles[below(kExtremeDoubles.size())];
            std::memcpy(blocks.data() + 8 * below(static_cast<std::size_t>(blocks.size()) / 8), &value, sizeof value);
        }
        break;
    case 3: // a byte of a block, such as a flag, neither 0 nor 1
        if (!blocks.isEmpty())
            blocks[static_cast<qsizetype>(below(static_cast<std::size_t>(blocks.size())))] = below(2) == 0 ? '\x02' : '\xFF';
        break;
    default: // a header length the file does not hold
        headerBytes = below(2) == 0 ? headerBytes + 1 + below(64) : std::numeric_limits<quint64>::max() - below(64);
        std::memcpy(bytes.data() + 16, &headerBytes, sizeof headerBytes);
        return;
    }
    headerBytes = static_cast<quint64>(header.size());
    std::memcpy(bytes.data() + 16, &headerBytes, sizeof headerBytes);
    bytes = bytes.left(kPreambleBytes) + header + blocks;
}

} // namespace gyre::fuzz
