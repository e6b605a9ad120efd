// prisca-cli's contract with scripts: --help and --version succeed, every other failure is one
// line on stderr and exit code 2.
#include <QProcess>
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
