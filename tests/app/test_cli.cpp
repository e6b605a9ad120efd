// prisca-cli's contract with scripts: --help and --version succeed, every other failure is one
// line on stderr and exit code 2.
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QtTest>

namespace {

struct CliResult {
    int exitCode = -1;
    QString out;
    QString err;
};

CliResult runCli(const QStringList& arguments) {
    QProcess process;
    process.start(QStringLiteral(PRISCA_CLI), arguments);
    CliResult result;
    if (!process.waitForFinished(30000) || process.exitStatus() != QProcess::NormalExit) {
        result.err = process.errorString();
        return result;
    }
    result.exitCode = process.exitCode();
    result.out = QString::fromLocal8Bit(process.readAllStandardOutput());
    result.err = QString::fromLocal8Bit(process.readAllStandardError());
    return result;
}

// The commands docs/architecture.md "Command line" plans.
const QStringList kPlannedCommands = {
    QStringLiteral("simulate"), QStringLiteral("demo"),   QStringLiteral("fit"),
    QStringLiteral("run"),      QStringLiteral("table1"), QStringLiteral("curve"),
    QStringLiteral("track"),    QStringLiteral("link"),
};

}  // namespace

class TestCli : public QObject {
    Q_OBJECT
  private slots:
    void help_exitsZeroAndListsEveryPlannedCommand();
    void architectureDoc_namesTheCommandsHelpLists();
    void version_printsTheProjectVersion();
    void unknownCommand_exitsTwoWithOneLineError();
    void noCommand_exitsTwo();
    void unknownOption_exitsTwoWithOneLineError();
};

void TestCli::help_exitsZeroAndListsEveryPlannedCommand() {
    const CliResult result = runCli({QStringLiteral("--help")});
    QCOMPARE(result.exitCode, 0);
    for (const QString& command : kPlannedCommands) {
        const QRegularExpression listed(QStringLiteral("^\\s+%1\\s").arg(command),
                                        QRegularExpression::MultilineOption);
        QVERIFY2(result.out.contains(listed), qPrintable(command + u'\n' + result.out));
    }
    QVERIFY(result.out.contains(QStringLiteral("--version")));
}

void TestCli::architectureDoc_namesTheCommandsHelpLists() {
    const CliResult result = runCli({QStringLiteral("--help")});
    QCOMPARE(result.exitCode, 0);
    // --help: one command a line between "Commands:" and the blank line after them.
    QStringList listed;
    const QString block =
        result.out.section(QStringLiteral("Commands:\n"), 1).section(QStringLiteral("\n\n"), 0, 0);
    for (const QString& line : block.split(QLatin1Char('\n'), Qt::SkipEmptyParts)) {
        listed << line.trimmed().section(QLatin1Char(' '), 0, 0);
    }
    QVERIFY2(listed.size() >= 10, qPrintable(result.out));
    // docs/architecture.md, "Command line": "Commands (N, as `prisca-cli --help` lists them):
    // `a`, `b`, ...;".
    QFile doc(QStringLiteral(PRISCA_SOURCE_DIR "/docs/architecture.md"));
    QVERIFY(doc.open(QIODevice::ReadOnly));
    const QString text = QString::fromUtf8(doc.readAll());
    const QRegularExpression sentence(QStringLiteral(
        "Commands \\((\\d+),\\s+as\\s+`prisca-cli\\s+--help`\\s+lists\\s+them\\):([^;]*);"));
    const QRegularExpressionMatch match = sentence.match(text);
    QVERIFY2(match.hasMatch(), "docs/architecture.md has no command list sentence");
    QStringList documented;
    QRegularExpressionMatchIterator names =
        QRegularExpression(QStringLiteral("`([a-z0-9-]+)`")).globalMatch(match.captured(2));
    while (names.hasNext()) {
        documented << names.next().captured(1);
    }
    QCOMPARE(documented, listed);
    QCOMPARE(match.captured(1).toInt(), static_cast<int>(listed.size()));
}

void TestCli::version_printsTheProjectVersion() {
    const CliResult result = runCli({QStringLiteral("--version")});
    QCOMPARE(result.exitCode, 0);
    QCOMPARE(result.out.trimmed(), QStringLiteral("prisca-cli " PRISCA_VERSION));
}

void TestCli::unknownCommand_exitsTwoWithOneLineError() {
    const CliResult result = runCli({QStringLiteral("bogus")});
    QCOMPARE(result.exitCode, 2);
    QCOMPARE(result.err, QStringLiteral("prisca-cli: unknown command 'bogus' (see --help)\n"));
    QCOMPARE(result.out, QString());
}

void TestCli::noCommand_exitsTwo() {
    const CliResult result = runCli({});
    QCOMPARE(result.exitCode, 2);
    QCOMPARE(result.err, QStringLiteral("prisca-cli: no command given (see --help)\n"));
}

void TestCli::unknownOption_exitsTwoWithOneLineError() {
    const CliResult result = runCli({QStringLiteral("--bogus")});
    QCOMPARE(result.exitCode, 2);
    QVERIFY2(result.err.startsWith(QStringLiteral("prisca-cli: ")), qPrintable(result.err));
    QCOMPARE(result.err.count(u'\n'), 1);
}

QTEST_GUILESS_MAIN(TestCli)
#include "test_cli.moc"
