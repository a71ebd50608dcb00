#pragma once
// The verbs of gyre-cli. Each parses the arguments that follow its name, does its work and returns
// normally on success, printing what it has to say to standard output; it throws UsageError for a bad command line, InputError or OutputError for a
// file it cannot use, and leaves no output file behind on any error.

#include <QStringList>

namespace gyre::cli {

void runConvert(const QStringList& arguments);
void runInterpolate(const QStringList& arguments);
void runSubdivide(const QStringList& arguments);
void runFit(const QStringList& arguments);
void runInfo(const QStringList& arguments);
void runKeys(const QStringList& arguments);
void runImport(const QStringList& arguments);
void runExport(const QStringList& arguments);
void runBake(const QStringList& arguments);

} // namespace gyre::cli
