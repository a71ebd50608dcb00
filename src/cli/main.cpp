// gyre-cli: batch verbs over pose CSV files and projects. main() dispatches to a verb and turns every error into
// a message on standard error and an exit status, so that no exception ever leaves the program.

#include "cli/command_line.h"
#include "cli/help_text.h"
#include "cli/verbs.h"

#include <QCoreApplication>
#include <QLatin1String>

#include <cstdio>
#include <exception>
#include <new>
#include <string_view>
#include <vector>

namespace {

using namespace gyre::cli;

constexpr int kFailed = 1; // bad input, an output file that cannot be written, or anything else
constexpr int kBadUsage = 2;

struct Verb {
    QLatin1String name;
    void (*run)(const QStringList& arguments);
    QString (*help)();
};

const Verb kVerbs[] = {
    {QLatin1String("convert"), runConvert, convertHelp},
    {QLatin1String("interpolate"), runInterpolate, interpolateHelp},
    {QLatin1String("subdivide"), runSubdivide, subdivideHelp},
    {QLatin1String("fit"), runFit, fitHelp},
    {QLatin1String("info"), runInfo, infoHelp},
    {QLatin1String("keys"), runKeys, keysHelp},
    {QLatin1String("bake"), runBake, bakeHelp},
    {QLatin1String("import"), runImport, importHelp},
    {QLatin1String("export"), runExport, exportHelp},
};

const Verb* findVerb(const QString& name)
{
    for (const Verb& verb : kVerbs)
        if (verb.name == name)
            return &verb;
    return nullptr;
}

const Verb& requireVerb(const QString& name)
{
    if (const Verb* verb = findVerb(name))
        return *verb;
    if (name.startsWith(QLatin1Char('-')))
        throw UsageError("unknown option " + name.toStdString() + " (see gyre-cli --help)");
    std::vector<std::string_view> names;
    for (const Verb& verb : kVerbs)
        names.push_back(std::string_view(verb.name.data(), static_cast<std::size_t>(verb.name.size())));
    throw UsageError("unknown verb '" + name.toStdString() + "'; the verbs are " + alternatives(names) +
                     " (see gyre-cli --help)");
}

void print(QString text)
{
    if (!text.endsWith(QLatin1Char('\n')))
        text += QLatin1Char('\n');
    std::fputs(qPrintable(text), stdout);
}

void printError(const char* message) { std::fprintf(stderr, "gyre-cli: %s\n", message); }

bool asksForHelp(const QStringList& arguments)
{
    return arguments.contains(QLatin1String("--help")) || arguments.contains(QLatin1String("-h"));
}

// `gyre-cli help` or `gyre-cli help VERB`.
void printHelp(const QStringList& verbs)
{
    if (verbs.size() > 1)
        throw UsageError("help takes one verb (see gyre-cli --help)");
    print(verbs.isEmpty() ? generalHelp() : requireVerb(verbs.front()).help());
}

void dispatch(const QStringList& arguments)
{
    if (arguments.isEmpty())
        throw UsageError("no verb given (see gyre-cli --help)");
    const QString& first = arguments.front();
    const QStringList rest = arguments.mid(1);
    if (first == QLatin1String("--help") || first == QLatin1String("-h"))
        print(generalHelp());
    else if (first == QLatin1String("--version"))
        print(QStringLiteral("gyre-cli " GYRE_VERSION));
    else if (first == QLatin1String("help"))
        printHelp(rest);
    else if (const Verb& verb = requireVerb(first); asksForHelp(rest))
        print(verb.help());
    else
        verb.run(rest);
}

} // namespace

int main(int argc, char* argv[])
{
    try {
        const QCoreApplication application(argc, argv);
        dispatch(QCoreApplication::arguments().mid(1));
        return 0;
    } catch (const UsageError& error) {
        printError(error.what());
        return kBadUsage;
    } catch (const std::bad_alloc&) {
        printError("out of memory");
        return kFailed;
    } catch (const std::exception& error) {
        printError(error.what());
        return kFailed;
    } catch (...) {
        printError("internal error: an unknown exception");
        return kFailed;
    }
}
