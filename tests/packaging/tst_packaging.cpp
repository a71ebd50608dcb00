// What the package puts on the desktop holds together: the icon theme the build writes has every size
// (and its SVG draws the same picture, read back through Qt's own SVG renderer), the desktop entry names
// that icon, the installed program and the project file type, and the AppStream metadata's newest
// release is the project's version.

#include <QFile>
#include <QImage>
#include <QPainter>
#include <QSettings>
#include <QSvgRenderer>
#include <QTest>
#include <QXmlStreamReader>

#include <array>

namespace {

const QString kAppId = QStringLiteral(GYRE_APP_ID);
const QString kIconTheme = QStringLiteral(GYRE_ICON_THEME_DIR);
const QString kPackaging = QStringLiteral(GYRE_PACKAGING_DIR);
constexpr std::array kHicolorSizes{16, 22, 24, 32, 48, 64, 128, 256, 512};

QString pngPath(int size)
{
    return QStringLiteral("%1/%2x%2/apps/%3.png").arg(kIconTheme).arg(size).arg(kAppId);
}

// The share of pixels whose alpha is above half: the icon's filled area, independent of its colours.
double opaqueShare(const QImage& image)
{
    int opaque = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            opaque += qAlpha(image.pixel(x, y)) > 128 ? 1 : 0;
    return static_cast<double>(opaque) / (image.width() * image.height());
}

// Mean absolute difference of two equally sized images over all four channels, 0..255.
double meanDifference(const QImage& a, const QImage& b)
{
    double sum = 0.0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y);
            const QRgb q = b.pixel(x, y);
            sum += std::abs(qRed(p) - qRed(q)) + std::abs(qGreen(p) - qGreen(q)) + std::abs(qBlue(p) - qBlue(q))
                 + std::abs(qAlpha(p) - qAlpha(q));
        }
    return sum / (4.0 * a.width() * a.height());
}

// The `version` attribute of the first <release> in the metainfo: AppStream lists the newest first.
QString newestReleaseVersion(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QXmlStreamReader xml(&file);
    while (!xml.atEnd())
        if (xml.readNext() == QXmlStreamReader::StartElement && xml.name() == QLatin1String("release"))
            return xml.attributes().value(QLatin1String("version")).toString();
    return {};
}

} // namespace

class PackagingTest : public QObject {
    Q_OBJECT

private slots:
    void everyIconSizeIsWrittenAndDrawn_data()
    {
        QTest::addColumn<int>("size");
        for (const int size : kHicolorSizes)
            QTest::addRow("%dx%d", size, size) << size;
    }

    void everyIconSizeIsWrittenAndDrawn()
    {
        QFETCH(int, size);
        const QImage image(pngPath(size));
        QVERIFY2(!image.isNull(), qPrintable(pngPath(size)));
        QCOMPARE(image.size(), QSize(size, size));
        QVERIFY(image.hasAlphaChannel());
        // The rounded square fills most of the icon (about 85% at large sizes, less at 16 px where its
        // antialiased edge is a larger share) and leaves its corners clear.
        QVERIFY2(opaqueShare(image) > 0.7, qPrintable(QString::number(opaqueShare(image))));
        QCOMPARE(qAlpha(image.pixel(0, 0)), 0);
    }

    void theScalableIconDrawsWhatThePngsShow()
    {
        const QString svgPath = QStringLiteral("%1/scalable/apps/%2.svg").arg(kIconTheme, kAppId);
        QSvgRenderer renderer(svgPath);
        QVERIFY2(renderer.isValid(), qPrintable(svgPath));
        constexpr int kSize = 256;
        QImage drawn(kSize, kSize, QImage::Format_ARGB32);
        drawn.fill(Qt::transparent);
        QPainter painter(&drawn);
        painter.setRenderHint(QPainter::Antialiasing);
        renderer.render(&painter, QRectF(0, 0, kSize, kSize));
        painter.end();
        const QImage png = QImage(pngPath(kSize)).convertToFormat(QImage::Format_ARGB32);
        // Antialiasing and gradient rounding differ by a level or two; a missing shape differs by tens.
        QVERIFY2(meanDifference(drawn, png) < 3.0, qPrintable(QString::number(meanDifference(drawn, png))));
    }

    void theDesktopEntryNamesTheIconTheProgramAndTheProjectType()
    {
        QSettings entry(QStringLiteral("%1/%2.desktop").arg(kPackaging, kAppId), QSettings::IniFormat);
        entry.beginGroup(QStringLiteral("Desktop Entry"));
        QCOMPARE(entry.value(QStringLiteral("Icon")).toString(), kAppId);
        QCOMPARE(entry.value(QStringLiteral("Exec")).toString(), QStringLiteral("gyre %f"));
        QVERIFY(entry.value(QStringLiteral("MimeType")).toString().contains(QStringLiteral("application/x-gyre-project")));
        QFile mime(QStringLiteral("%1/%2.mime.xml").arg(kPackaging, kAppId));
        QVERIFY(mime.open(QIODevice::ReadOnly));
        const QByteArray types = mime.readAll();
        QVERIFY(types.contains(R"(type="application/x-gyre-project")"));
        QVERIFY(types.contains(R"(pattern="*.gyre")"));
    }

    void theMetainfoReleasesTheProjectVersion()
    {
        QCOMPARE(newestReleaseVersion(QStringLiteral("%1/%2.metainfo.xml").arg(kPackaging, kAppId)),
                 QStringLiteral(GYRE_VERSION));
    }
};

QTEST_MAIN(PackagingTest)
#include "tst_packaging.moc"
