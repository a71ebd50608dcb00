// gyre-samples DIR: writes the bundled sample projects into DIR (resources/samples when they change).

#include "model/project_file.h"
#include "samples/sample_scenes.h"

#include <QCoreApplication>
#include <QDir>

#include <cstdio>
#include <stdexcept>

int main(int argc, char** argv)
{
    QCoreApplication application(argc, argv);
    const QStringList arguments = application.arguments();
    if (arguments.size() != 2) {
        std::fprintf(stderr, "Usage: gyre-samples DIR\nWrites Gyre's sample projects into DIR.\n");
        return 2;
    }
    const QDir directory(arguments[1]);
    if (!directory.exists()) {
        std::fprintf(stderr, "gyre-samples: %s: no such folder\n", qPrintable(arguments[1]));
        return 1;
    }
    try {
        for (const gyre::samples::SampleScene& sample : gyre::samples::allSamples())
            gyre::model::writeProject(directory.filePath(sample.fileName), sample.scene);
    } catch (const std::runtime_error& error) { // a file not written (OutputError) or a fit that failed
        std::fprintf(stderr, "gyre-samples: %s\n", error.what());
        return 1;
    }
    return 0;
}
