#pragma once
// What `gyre-cli --help` and `gyre-cli help VERB` print. docs/pose-csv.md and docs/file-format.md say
// the same at length.

#include <QString>

namespace gyre::cli {

QString generalHelp();
QString convertHelp();
QString interpolateHelp();
QString subdivideHelp();
QString fitHelp();
QString infoHelp();
QString keysHelp();
QString importHelp();
QString exportHelp();
QString bakeHelp();

} // namespace gyre::cli
