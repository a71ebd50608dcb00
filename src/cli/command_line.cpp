#include "cli/command_line.h"

#include "core/number_text.h"
#include "io/pose_csv.h"
#include "model/output_target.h"
#include "model/value_checks.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <cstdio>
#include <filesystem>
#include <system_error>
#include <utility>

namespace gyre::cli {

namespace {

const QString kOutputOption = QStringLiteral("o");
const QString kOrderOption = QStringLiteral("order");
const QString kIntrinsicOption = QStringLiteral("intrinsic");
const QString kExtrinsicOption = QStringLiteral("extrinsic");

QString dashed(const QString& name) { return (name.size() == 1 ? "-" : "--") + name; }

std::string quoted(const QString& text) { return "'" + text.toStdString() + "'"; }

// Where a path that may not exist yet would be: its folder's canonical path (symbolic links resolved)
// and its name.
QString locationOf(const QString& path)
{
    const QFileInfo info(path);
    const QString folder = info.absoluteDir().canonicalPath();
    return folder.isEmpty() ? info.absoluteFilePath() : folder + QLatin1Char('/') + info.fileName();
}

// Whether two paths name one file: where both exist, the same device and inode, so that hard links
// and symbolic links are seen through; otherwise the same location.
bool isSameFile(const QString& a, const QString& b)
{
    if (QFileInfo::exists(a) && QFileInfo::exists(b)) {
        std::error_code error;
        const bool same = std::filesystem::equivalent(std::filesystem::path(QFile::encodeName(a).toStdString()),
                                                      std::filesystem::path(QFile::encodeName(b).toStdString()), error);
        if (!error)
            return same;
    }
    return locationOf(a) == locationOf(b);
}

bool isStandardOutput(const QString& path) { return path == OutputTarget::kStandardOutput; }

} // namespace

VerbCommandLine::VerbCommandLine(QString verb, const QStringList& arguments,
                                 const QList<QCommandLineOption>& verbOptions, OutputFile output)
    : verb_(std::move(verb))
{
    QList<QCommandLineOption> options = verbOptions;
    if (output != OutputFile::None)
        options.append(QCommandLineOption({kOutputOption, QStringLiteral("output")}, {}, QStringLiteral("file")));
    parser_.addOptions(options);
    // QCommandLineParser::parse skips the first argument, the program's name.
    if (!parser_.parse(QStringList{QStringLiteral("gyre-cli")} + arguments)) {
        const QStringList unknown = parser_.unknownOptionNames();
        if (!unknown.isEmpty())
            throw error("unknown option " + dashed(unknown.front()).toStdString());
        throw error(parser_.errorText().toStdString());
    }
    checkSingleValues(options);
    const QStringList inputs = parser_.positionalArguments();
    if (inputs.isEmpty())
        throw error("no input file");
    if (inputs.size() > 1)
        throw error("one input file expected, got " + std::to_string(inputs.size()) + ": " +
                    inputs.join(QStringLiteral(", ")).toStdString());
    inputPath_ = inputs.front();
    if (output == OutputFile::None)
        return;
    outputPath_ = requiredValue(kOutputOption);
    if (output == OutputFile::Required || !QFileInfo(outputPath_).isFile())
        refuseSharedFiles({{"the input file", inputPath_}}, {{"-o", outputPath_}});
}

void VerbCommandLine::refuseSharedFiles(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs) const
{
    const auto refuse = [this](const NamedFile& first, const NamedFile& second) {
        throw error(first.name + " and " + second.name + " name the same file " + quoted(second.path) +
                    "; give the output another name");
    };
    for (std::size_t i = 0; i < outputs.size(); ++i) {
        const NamedFile& output = outputs[i];
        if (isStandardOutput(output.path)) {
            for (std::size_t j = 0; j < i; ++j)
                if (isStandardOutput(outputs[j].path))
                    throw error(outputs[j].name + " and " + output.name + " both name standard output (-)");
            continue;
        }
        for (const NamedFile& input : inputs)
            if (isSameFile(input.path, output.path))
                refuse(input, output);
        for (std::size_t j = 0; j < i; ++j)
            if (!isStandardOutput(outputs[j].path) && isSameFile(outputs[j].path, output.path))
                refuse(outputs[j], output);
    }
}

void VerbCommandLine::checkSingleValues(const QList<QCommandLineOption>& options) const
{
    for (const QCommandLineOption& option : options) {
        const QString name = option.names().front();
        if (!option.valueName().isEmpty() && parser_.values(name).size() > 1)
            throw error("option " + dashed(name).toStdString() + " given more than once");
    }
}

QString VerbCommandLine::requiredValue(const QString& option) const
{
    if (!parser_.isSet(option))
        throw error("missing option " + dashed(option).toStdString());
    return parser_.value(option);
}

double VerbCommandLine::number(const QString& option) const
{
    try {
        return parseFiniteNumber(requiredValue(option).toStdString());
    } catch (const std::invalid_argument& problem) {
        throw error(dashed(option).toStdString() + ": " + problem.what());
    }
}

double VerbCommandLine::positiveNumber(const QString& option) const
{
    const double value = number(option);
    if (!(value > 0.0))
        throw error(dashed(option).toStdString() + ": " + quoted(parser_.value(option)) + " is not positive");
    return value;
}

double VerbCommandLine::frameRate(const QString& option) const
{
    const double value = positiveNumber(option);
    try {
        return model::frameRate(value);
    } catch (const std::invalid_argument& problem) {
        throw error(dashed(option).toStdString() + ": " + problem.what());
    }
}

std::vector<double> VerbCommandLine::numberList(const QString& option) const
{
    std::vector<double> numbers;
    try {
        for (const QString& item : requiredValue(option).split(QLatin1Char(',')))
            numbers.push_back(parseFiniteNumber(item.toStdString()));
    } catch (const std::invalid_argument& problem) {
        throw error(dashed(option).toStdString() + ": " + problem.what());
    }
    return numbers;
}

int VerbCommandLine::nonNegativeInteger(const QString& option) const
{
    const QString text = requiredValue(option);
    bool ok = false;
    const int value = text.toInt(&ok);
    if (!ok || value < 0)
        throw error(dashed(option).toStdString() + ": " + quoted(text) + " is not a whole number ≥ 0");
    return value;
}

EulerConvention VerbCommandLine::eulerConvention() const
{
    if (parser_.isSet(kIntrinsicOption) && parser_.isSet(kExtrinsicOption))
        throw error("--intrinsic and --extrinsic exclude each other");
    const AngleFrame frame = parser_.isSet(kIntrinsicOption) ? AngleFrame::Intrinsic : AngleFrame::Extrinsic;
    const QString order = parser_.isSet(kOrderOption) ? parser_.value(kOrderOption) : QStringLiteral("xyz");
    const auto convention = EulerConvention::parse(order.toStdString(), frame);
    if (!convention)
        throw error("--order: " + quoted(order) +
                    " is not an axis order; give three of x, y, z with no axis twice in a row, such as xyz or zxz");
    return *convention;
}

UsageError VerbCommandLine::error(std::string_view message) const
{
    return UsageError(verb_.toStdString() + ": " + std::string(message) + " (see gyre-cli help " +
                      verb_.toStdString() + ")");
}

model::BakeRange checkedOutputRange(const model::BakeRange& range, std::size_t keyCount,
                                    const VerbCommandLine& commandLine)
{
    if (!(model::bakeSampleBound(range, keyCount) <= static_cast<double>(io::kMaxPoseRows)))
        throw commandLine.error("--fps " + formatNumber(range.fps) + " over " + formatNumber(range.end - range.start) +
                                " s gives more than " + std::to_string(io::kMaxPoseRows) + " samples");
    return range;
}

QList<QCommandLineOption> eulerOptions()
{
    return {QCommandLineOption(kOrderOption, {}, QStringLiteral("axes")), QCommandLineOption(kIntrinsicOption),
            QCommandLineOption(kExtrinsicOption)};
}

std::string alternatives(const std::vector<std::string_view>& names)
{
    std::string text;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0)
            text += i + 1 == names.size() ? " or " : ", ";
        text += names[i];
    }
    return text;
}

void warn(std::string_view message)
{
    std::fprintf(stderr, "gyre-cli: warning: %.*s\n", static_cast<int>(message.size()), message.data());
}

} // namespace gyre::cli
