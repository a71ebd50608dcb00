#pragma once
// What `gyre-cli --help` and `gyre-cli help VERB` print. docs/pose-csv.md says the same at length.

#include <QString>

namespace gyre::cli {

QString generalHelp();
QString convertHelp();
QString interpolateHelp();
QString subdivideHelp();
QString fitHelp();

} // namespace gyre::cli
