#pragma once
// The command line of one verb: an input file, `-o FILE`, and the verb's own options, in any order.
// Everything wrong with it is a UsageError whose message names the verb and the option.

#include "core/euler_angles.h"
#include "core/name_table.h"
#include "model/track_evaluation.h"

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QList>
#include <QString>
#include <QStringList>

#include <array>
#include <optional>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace gyre::cli {

// A command line that cannot be run as given; gyre-cli exits with status 2.
class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Whether a verb writes a file named by -o, or prints what it has to say. Only an output that holds
// what its input held, in another form, may replace the input (a regular file, read whole before
// the output is written); any other output that names the input is refused, as it would lose it.
enum class OutputFile { Required, MayReplaceInput, None };

// A file of the command line with what names it: "-o", "--report", or "the input file".
struct NamedFile {
    std::string name;
    QString path;
};

class VerbCommandLine {
public:
    // Parses the arguments after the verb. Throws UsageError for an unknown option, a missing
    // value, a value option given twice, no -o where the verb writes a file, not exactly one
    // input file, or an output that is the input file (unless it may replace it). `-o -` is standard
    // output.
    VerbCommandLine(QString verb, const QStringList& arguments, const QList<QCommandLineOption>& verbOptions,
                    OutputFile output = OutputFile::Required);
    VerbCommandLine(const VerbCommandLine&) = delete;
    VerbCommandLine& operator=(const VerbCommandLine&) = delete;

    const QString& inputPath() const { return inputPath_; }
    const QString& outputPath() const { return outputPath_; } // empty for OutputFile::None
    bool isSet(const QString& option) const { return parser_.isSet(option); }

    // The value of an option that must be given.
    QString requiredValue(const QString& option) const;
    // A required option's value as one of the names in `choices`.
    template <class Choice, std::size_t Count>
    Choice choice(const QString& option, const NameTable<Choice, Count>& choices) const;
    // A required option's value as a finite number.
    double number(const QString& option) const;
    // A required option's value as a finite number > 0.
    double positiveNumber(const QString& option) const;
    // A required option's value as a frame rate in (0, model::kMaxFps].
    double frameRate(const QString& option) const;
    // A required option's value as comma-separated finite numbers, e.g. "1,2,3".
    std::vector<double> numberList(const QString& option) const;
    // A required option's value as an integer ≥ 0.
    int nonNegativeInteger(const QString& option) const;
    // The convention of --order (default xyz) and --intrinsic or --extrinsic (default extrinsic),
    // for a verb that has eulerOptions().
    EulerConvention eulerConvention() const;

    // Throws UsageError naming both and the file when an output is the same file as an input (by
    // device and inode where both exist, else by canonical folder and name) or as another output,
    // so that no output overwrites what the verb reads or writes besides. Standard output is no
    // input file, and the same output only as another `-`.
    void refuseSharedFiles(const std::vector<NamedFile>& inputs, const std::vector<NamedFile>& outputs) const;

    // A UsageError that names the verb, for the caller to throw.
    UsageError error(std::string_view message) const;

private:
    void checkSingleValues(const QList<QCommandLineOption>& options) const;

    QString verb_;
    QCommandLineParser parser_;
    QString inputPath_;
    QString outputPath_;
};

// `range`, for a verb that writes a motion at its frames and `keyCount` keys; a UsageError naming
// --fps when that would be more rows than a pose file may hold.
model::BakeRange checkedOutputRange(const model::BakeRange& range, std::size_t keyCount,
                                    const VerbCommandLine& commandLine);

// --order, --intrinsic and --extrinsic.
QList<QCommandLineOption> eulerOptions();

// "a, b or c", for messages that list the accepted values.
std::string alternatives(const std::vector<std::string_view>& names);

// Prints `gyre-cli: warning: message` to standard error.
void warn(std::string_view message);

template <class Choice, std::size_t Count>
Choice VerbCommandLine::choice(const QString& option, const NameTable<Choice, Count>& choices) const
{
    const std::string value = requiredValue(option).toStdString();
    if (const std::optional<Choice> chosen = valueNamed(choices, value))
        return *chosen;
    std::vector<std::string_view> names;
    for (const auto& entry : choices)
        names.push_back(entry.second);
    throw error("--" + option.toStdString() + ": unknown value '" + value + "'; expected " + alternatives(names));
}

} // namespace gyre::cli
