#pragma once

// What the demonstration CSV tests share: the canonical good file, edits of it, and comparisons.

#include "core/DemonstrationCsv.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <random>

using prisca::core::checkDemonstrationForCsv;
using prisca::core::CsvReadOptions;
using prisca::core::Demonstration;
using prisca::core::FileError;
using prisca::core::formatDemonstrationCsv;
using prisca::core::parseDemonstrationCsv;
using prisca::core::readDemonstrationCsv;
using prisca::core::writeDemonstrationCsv;

namespace {

// The canonical good file; most bad inputs are made by editing one line of it.
const QByteArray kGood =
    "# prisca-demonstration 1\n"                                    // line 1
    "# plant: slidecar\n"                                           // line 2
    "# dt: 0.025\n"                                                 // line 3
    "# states: x[m], y[m], psi[rad], vx[m/s], vy[m/s], r[rad/s]\n"  // line 4
    "# actions: throttle[1], steering[1]\n"                         // line 5
    "t,x,y,psi,vx,vy,r,throttle,steering\n"                         // line 6
    "0,0,0,0,0,0,0,0.5,0\n"                                         // line 7
    "0.025,0.001,0,0,0.08,0,0,0.5,0\n"                              // line 8
    "0.05,0.004,0,0,0.16,0,0,0.5,0.1\n"                             // line 9
    "0.075,0.009,0,0,0.24,0,0,0.5,0.1\n";                           // line 10

const QString kSource = QStringLiteral("memory.csv");

// kGood with its 1-based line number `line` replaced; a null replacement removes the line.
inline QByteArray withLine(int line, const QByteArray& replacement,
                           const QByteArray& text = kGood) {
    QList<QByteArray> lines = text.split('\n');
    if (replacement.isNull()) {
        lines.removeAt(line - 1);
    } else {
        lines[line - 1] = replacement;
    }
    return lines.join('\n');
}

// kGood with field `column` (1-based) of line `line` replaced.
inline QByteArray withField(int line, int column, const QByteArray& value) {
    QList<QByteArray> fields = kGood.split('\n').at(line - 1).split(',');
    fields[column - 1] = value;
    return withLine(line, fields.join(','));
}

// The error of a parse that must fail, or nullopt when it unexpectedly succeeded.
inline std::optional<FileError> errorOf(const QByteArray& text,
                                        const CsvReadOptions& options = {}) {
    FileError error;
    if (parseDemonstrationCsv(text, kSource, &error, options)) {
        return std::nullopt;
    }
    return error;
}

inline bool sameBits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

inline bool sameBits(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    if (a.rows() != b.rows() || a.cols() != b.cols()) {
        return false;
    }
    for (Eigen::Index i = 0; i < a.rows(); ++i) {
        for (Eigen::Index j = 0; j < a.cols(); ++j) {
            if (!sameBits(a(i, j), b(i, j))) {
                return false;
            }
        }
    }
    return true;
}

inline bool sameDemonstration(const Demonstration& a, const Demonstration& b) {
    return a.plant == b.plant && sameBits(a.dt, b.dt) && a.stateNames == b.stateNames &&
           a.stateUnits == b.stateUnits && a.actionNames == b.actionNames &&
           a.actionUnits == b.actionUnits && a.metadata == b.metadata &&
           sameBits(Eigen::MatrixXd(a.time), Eigen::MatrixXd(b.time)) &&
           sameBits(a.states, b.states) && sameBits(a.actions, b.actions);
}

// A slide-car demonstration of T samples at dt = 0.025 s with smooth, non-round values.
inline Demonstration makeDemonstration(int samples) {
    Demonstration demo;
    demo.plant = QStringLiteral("slidecar");
    demo.dt = 0.025;
    demo.stateNames = QStringList{"x", "y", "psi", "vx", "vy", "r"};
    demo.stateUnits = QStringList{"m", "m", "rad", "m/s", "m/s", "rad/s"};
    demo.actionNames = QStringList{"throttle", "steering"};
    demo.actionUnits = QStringList{"1", "1"};
    demo.time.resize(samples);
    demo.states.resize(samples, 6);
    demo.actions.resize(samples, 2);
    for (int k = 0; k < samples; ++k) {
        const double t = k * demo.dt;
        demo.time[k] = t;
        for (int c = 0; c < 6; ++c) {
            demo.states(k, c) = std::sin(0.7 * t + c) * (c + 1) / 3.0;
        }
        demo.actions(k, 0) = 0.5 + 0.1 * std::cos(t);
        demo.actions(k, 1) = std::sin(2.0 * t) / 7.0;
    }
    return demo;
}

inline int lineCount(const QByteArray& text) {
    return int(text.count('\n')) + 1;
}

// Fails the current test unless parsing `text` fails at `line`:`column` with a message
// mentioning every string in `mentions`.
inline void expectError(const QByteArray& text, int line, int column, const QStringList& mentions,
                        const CsvReadOptions& options = {}) {
    const std::optional<FileError> error = errorOf(text, options);
    QVERIFY2(error, "the bad input was accepted");
    QCOMPARE(error->path, kSource);
    QVERIFY2(!error->message.isEmpty(), "empty error message");
    QVERIFY2(!error->message.contains(QLatin1Char('\n')), qPrintable(error->message));
    QCOMPARE(error->line, line);
    QCOMPARE(error->column, column);
    for (const QString& mention : mentions) {
        QVERIFY2(error->message.contains(mention),
                 qPrintable(QStringLiteral("'%1' not in: %2").arg(mention, error->message)));
    }
}

}  // namespace
