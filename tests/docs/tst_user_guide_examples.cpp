// The user guide (docs/user-guide.md) against the repository and the real gyre-cli: every picture and
// document it links to exists, and every picture is a PNG at most kMostPictureWidth pixels wide; every
// fenced block that runs gyre-cli is marked as an example, and runs as written, with gyre-cli on the
// PATH, from a folder that holds the bundled samples where the repository does, exiting 0 and, where
// the guide shows what it prints, printing exactly that; and every verb that gyre-cli --help lists has
// an example.

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImageReader>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

namespace {

constexpr int kMostPictureWidth = 1600;
constexpr int kExampleTimeoutMilliseconds = 120'000;
// The line before a fenced block that makes it an example this test runs; HTML comments do not show
// where the guide is rendered.
const QString kExampleMark = QStringLiteral("<!-- example -->");

const QString kGuidePath = QStringLiteral(GYRE_SOURCE_DIR "/docs/user-guide.md");

QString guideText()
{
    QFile file(kGuidePath);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text))
        qFatal("Cannot read %s", qPrintable(kGuidePath));
    return QString::fromUtf8(file.readAll());
}

struct CodeBlock {
    int line = 0; // of the opening fence, from 1
    bool markedAsExample = false;
    QString text;
    // What the guide says the block prints: the indented block after a line "prints" that follows it.
    QString printed;
};

// The indented block after the line "prints" at or after `index`, past blank lines; empty without one.
QString printedAfter(const QStringList& lines, qsizetype index)
{
    const auto skipBlankLines = [&lines](qsizetype i) {
        while (i < lines.size() && lines[i].trimmed().isEmpty())
            ++i;
        return i;
    };
    qsizetype i = skipBlankLines(index);
    if (i >= lines.size() || lines[i] != QLatin1String("prints"))
        return {};
    QString printed;
    for (i = skipBlankLines(i + 1); i < lines.size() && lines[i].startsWith(QLatin1String("    ")); ++i)
        printed += lines[i].mid(4) + QLatin1Char('\n');
    return printed;
}

// The guide's fenced code blocks, each with whether the line before it is kExampleMark.
std::vector<CodeBlock> codeBlocks()
{
    const QStringList lines = guideText().split(QLatin1Char('\n'));
    std::vector<CodeBlock> blocks;
    for (qsizetype i = 0; i < lines.size(); ++i) {
        if (!lines[i].startsWith(QLatin1String("```")))
            continue;
        CodeBlock block;
        block.line = static_cast<int>(i + 1);
        block.markedAsExample = i > 0 && lines[i - 1].trimmed() == kExampleMark;
        for (++i; i < lines.size() && !lines[i].startsWith(QLatin1String("```")); ++i)
            block.text += lines[i] + QLatin1Char('\n');
        block.printed = printedAfter(lines, i + 1);
        blocks.push_back(block);
    }
    return blocks;
}

// The targets of the guide's Markdown links and pictures that are files of the repository, without
// any #anchor.
QStringList linkedFiles()
{
    static const QRegularExpression link(QStringLiteral(R"(\]\(([^)#\s]+)(#[^)\s]*)?\))"));
    QStringList files;
    for (const QRegularExpressionMatch& match : link.globalMatch(guideText())) {
        const QString target = match.captured(1);
        if (!target.contains(QLatin1String("://")))
            files.append(target);
    }
    return files;
}

// Copies every file of `from` into `to`, which is made.
void copyFolder(const QString& from, const QString& to)
{
    if (!QDir().mkpath(to))
        qFatal("Cannot make %s", qPrintable(to));
    for (const QFileInfo& file : QDir(from).entryInfoList(QDir::Files))
        if (!QFile::copy(file.filePath(), QDir(to).filePath(file.fileName())))
            qFatal("Cannot copy %s", qPrintable(file.filePath()));
}

} // namespace

class TestUserGuideExamples : public QObject {
    Q_OBJECT

private slots:
    void everyLinkedFileExists()
    {
        const QStringList files = linkedFiles();
        QVERIFY(files.contains(QStringLiteral("fit.md")));
        const QDir docs(QStringLiteral(GYRE_SOURCE_DIR "/docs"));
        for (const QString& file : files)
            QVERIFY2(QFileInfo::exists(docs.filePath(file)), qPrintable(file));
    }

    void everyPictureIsAPngOfAtMost1600Pixels()
    {
        const QDir docs(QStringLiteral(GYRE_SOURCE_DIR "/docs"));
        int pictures = 0;
        for (const QString& file : linkedFiles()) {
            if (!file.endsWith(QLatin1String(".png")))
                continue;
            QImageReader reader(docs.filePath(file));
            QCOMPARE(reader.format(), QByteArray("png"));
            QVERIFY2(reader.size().width() > 0 && reader.size().width() <= kMostPictureWidth, qPrintable(file));
            ++pictures;
        }
        QVERIFY(pictures > 0);
    }

    void everyBlockThatRunsGyreCliIsAnExample()
    {
        for (const CodeBlock& block : codeBlocks())
            if (block.text.contains(QLatin1String("gyre-cli")))
                QVERIFY2(block.markedAsExample, qPrintable(QStringLiteral("the block at line %1").arg(block.line)));
    }

    void everyExampleRunsAsWritten()
    {
        QTemporaryDir folder;
        QVERIFY(folder.isValid());
        copyFolder(QStringLiteral(GYRE_SOURCE_DIR "/resources/samples"), folder.filePath(QStringLiteral("resources/samples")));
        QProcessEnvironment environment = QProcessEnvironment::systemEnvironment();
        environment.insert(QStringLiteral("PATH"), QFileInfo(QStringLiteral(GYRE_CLI_PATH)).absolutePath()
                                                       + QLatin1Char(':') + environment.value(QStringLiteral("PATH")));
        int examples = 0;
        int printing = 0;
        for (const CodeBlock& block : codeBlocks()) {
            if (!block.markedAsExample)
                continue;
            QProcess shell;
            shell.setWorkingDirectory(folder.path());
            shell.setProcessEnvironment(environment);
            shell.start(QStringLiteral("sh"), {QStringLiteral("-e"), QStringLiteral("-c"), block.text});
            QVERIFY(shell.waitForFinished(kExampleTimeoutMilliseconds));
            const QString failure = QStringLiteral("the example at line %1: %2")
                                        .arg(block.line)
                                        .arg(QString::fromUtf8(shell.readAllStandardError()));
            QVERIFY2(shell.exitStatus() == QProcess::NormalExit && shell.exitCode() == 0, qPrintable(failure));
            if (!block.printed.isEmpty())
                QCOMPARE(QString::fromUtf8(shell.readAllStandardOutput()), block.printed);
            printing += block.printed.isEmpty() ? 0 : 1;
            ++examples;
        }
        QVERIFY(examples > 0);
        QVERIFY(printing > 0);
    }

    void everyVerbHasAnExample()
    {
        QProcess cli;
        cli.start(QStringLiteral(GYRE_CLI_PATH), {QStringLiteral("--help")});
        QVERIFY(cli.waitForFinished());
        QCOMPARE(cli.exitCode(), 0);
        // The verb list: "  convert      rewrite the rotation columns ...".
        static const QRegularExpression verbLine(QStringLiteral(R"(^  ([a-z]+) {2,}\S)"), QRegularExpression::MultilineOption);
        QString examples;
        for (const CodeBlock& block : codeBlocks())
            if (block.markedAsExample)
                examples += block.text;
        int verbs = 0;
        for (const QRegularExpressionMatch& match : verbLine.globalMatch(QString::fromUtf8(cli.readAllStandardOutput()))) {
            QVERIFY2(examples.contains(QStringLiteral("gyre-cli %1 ").arg(match.captured(1))), qPrintable(match.captured(1)));
            ++verbs;
        }
        QCOMPARE(verbs, 9);
    }
};

QTEST_MAIN(TestUserGuideExamples)
#include "tst_user_guide_examples.moc"
