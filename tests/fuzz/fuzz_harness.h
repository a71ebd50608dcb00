#pragma once
// The body of a libFuzzer harness: one input through readInput, aborting (which libFuzzer reports
// with the input) on any check the mutation test makes. Exceptions other than the readers' own
// leave LLVMFuzzerTestOneInput, which libFuzzer reports as a crash too.

#include "fuzz_inputs.h"

#include <QDir>
#include <QTemporaryDir>

#include <cstdint>
#include <cstdio>
#include <cstdlib>

namespace gyre::fuzz {

inline void fuzzOneInput(Reader reader, const char* fileName, const std::uint8_t* data, std::size_t size)
{
    static QTemporaryDir dir(QDir::temp().filePath(QStringLiteral("gyre-fuzz-XXXXXX")));
    const QString path = dir.filePath(QString::fromLatin1(fileName));
    const Outcome outcome = readInput(reader, QByteArray(reinterpret_cast<const char*>(data), static_cast<qsizetype>(size)), path);
    std::optional<std::string> problem;
    if (!outcome.accepted)
        problem = refusalProblem(reader, outcome.refusal, path);
    else if (outcome.evaluationProblem)
        problem = outcome.evaluationProblem;
    if (problem) {
        std::fprintf(stderr, "%s\n", problem->c_str());
        std::abort();
    }
}

} // namespace gyre::fuzz
