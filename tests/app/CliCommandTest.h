#pragma once
// What the prisca-cli command tests share: running the CLI the tests were built with
// (PRISCA_CLI) in a folder, reading its JSON and CSV, a pseudo-terminal kept from its children.

#include <fcntl.h>
#include <pty.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>
#include <QDir>
#include <QElapsedTimer>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <csignal>
#include <memory>
#include "core/FileIo.h"
#include "devices/PseudoTerminal.h"
#include "devices/SyntheticCamera.h"
#include "rig/PreTrialCheck.h"
#include "sim/MethodCatalog.h"
#include "sim/PlantCatalog.h"

namespace prisca::clitest {

// A pty for a CLI's link whose ends the CLI does not inherit: closing them unplugs it for good.
inline bool keptFromChildren(const Pty& pty) {
    return pty.master >= 0 && fcntl(pty.master, F_SETFD, FD_CLOEXEC) == 0 &&
           fcntl(pty.slave, F_SETFD, FD_CLOEXEC) == 0;
}

struct CliResult {
    int exitCode = -1;
    QString out;
    QString err;
};

inline CliResult runCli(const QStringList& arguments, const QString& directory) {
    QProcess process;
    process.setWorkingDirectory(directory);
    process.start(QStringLiteral(PRISCA_CLI), arguments);
    CliResult result;
    if (!process.waitForFinished(120000) || process.exitStatus() != QProcess::NormalExit) {
        result.err = QStringLiteral("did not finish: ") + process.errorString();
        return result;
    }
    result.exitCode = process.exitCode();
    result.out = QString::fromLocal8Bit(process.readAllStandardOutput());
    result.err = QString::fromLocal8Bit(process.readAllStandardError());
    return result;
}

inline QJsonObject parseJson(const QString& text) {
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(text.toUtf8(), &error);
    if (error.error != QJsonParseError::NoError || !document.isObject()) {
        qWarning("not JSON: %s\n%s", qPrintable(error.errorString()), qPrintable(text));
        return {};
    }
    return document.object();
}

inline void writeFile(const QString& path, const QByteArray& content) {
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(content);
}

// The last data row of a CSV written by the CLI, as numbers.
inline QList<double> lastRow(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        return {};
    }
    const QList<QByteArray> lines = file.readAll().trimmed().split('\n');
    QList<double> values;
    for (const QByteArray& field : lines.last().split(',')) {
        values << field.toDouble();
    }
    return values;
}

// A test's own folder, the CLI run in it, and the slide-car's demonstration (car.csv) every
// command test starts from.
class CliWorkspace {
  protected:
    QTemporaryDir dir_;
    QString path(const QString& name) const { return dir_.filePath(name); }
    CliResult cli(const QStringList& arguments) const { return runCli(arguments, dir_.path()); }
    /// For initTestCase: the folder made and car.csv written in it.
    void writeCarDemonstration() {
        QVERIFY(dir_.isValid());
        const CliResult demo =
            cli({"demo", "--plant", "slidecar", "--seed", "2", "--out", "car.csv"});
        QCOMPARE(demo.exitCode, 0);
        QVERIFY(QFile::exists(path("car.csv")));
    }
};

}  // namespace prisca::clitest
