// gyre-icons DIR: writes Gyre's icon into DIR as a hicolor icon theme, a PNG at every size of
// kAppIconSizes and a scalable SVG, under the application's id, for the desktop entry and the package.

#include "app/app_icon.h"

#include <QCoreApplication>
#include <QDir>
#include <QFont>
#include <QImage>
#include <QPainter>
#include <QSvgGenerator>

#include <cstdio>

namespace {

bool writePng(const QDir& theme, const QString& iconName, int size)
{
    const QString folder = QStringLiteral("%1x%1/apps").arg(size);
    if (!theme.mkpath(folder))
        return false;
    QImage image(size, size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter painter(&image);
    gyre::app::paintAppIcon(painter, size);
    painter.end();
    return image.save(theme.filePath(folder + QLatin1Char('/') + iconName + QStringLiteral(".png")));
}

bool writeSvg(const QDir& theme, const QString& iconName)
{
    const QString folder = QStringLiteral("scalable/apps");
    if (!theme.mkpath(folder))
        return false;
    constexpr int kSvgSize = 256;
    QSvgGenerator generator;
    generator.setFileName(theme.filePath(folder + QLatin1Char('/') + iconName + QStringLiteral(".svg")));
    generator.setSize(QSize(kSvgSize, kSvgSize));
    generator.setViewBox(QRect(0, 0, kSvgSize, kSvgSize));
    generator.setTitle(QStringLiteral("Gyre"));
    QPainter painter;
    if (!painter.begin(&generator))
        return false;
    // The generator writes the painter's font into every group; the default one's size of -1 makes
    // SVG readers warn, though the icon has no text.
    QFont font = painter.font();
    font.setPixelSize(12);
    painter.setFont(font);
    gyre::app::paintAppIcon(painter, kSvgSize);
    return painter.end();
}

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication application(argc, argv);
    const QStringList arguments = application.arguments();
    if (arguments.size() != 3) {
        std::fprintf(stderr, "Usage: gyre-icons DIR ICON-NAME\nWrites Gyre's icon into DIR as a hicolor theme.\n");
        return 2;
    }
    const QDir theme(arguments[1]);
    const QString& iconName = arguments[2];
    bool written = theme.mkpath(QStringLiteral("."));
    for (const int size : gyre::app::kAppIconSizes)
        written = written && writePng(theme, iconName, size);
    written = written && writeSvg(theme, iconName);
    if (!written) {
        std::fprintf(stderr, "gyre-icons: %s: cannot write the icons\n", qPrintable(arguments[1]));
        return 1;
    }
    return 0;
}
