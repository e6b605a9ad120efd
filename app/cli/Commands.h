#pragma once

#include <QStringList>

namespace prisca::app::cli {

// One function per command, each in its own file; CommandTable lists them.
int simulateCommand(const QStringList& arguments);
int demoCommand(const QStringList& arguments);
int fitCommand(const QStringList& arguments);
int runCommand(const QStringList& arguments);
int table1Command(const QStringList& arguments);
int curveCommand(const QStringList& arguments);
int lemma41Command(const QStringList& arguments);
int linkCommand(const QStringList& arguments);
int trackCommand(const QStringList& arguments);
int calibrateCameraCommand(const QStringList& arguments);
int calibrateFloorCommand(const QStringList& arguments);
int rigCommand(const QStringList& arguments);
int replayCommand(const QStringList& arguments);
int doctorCommand(const QStringList& arguments);
int methodsCommand(const QStringList& arguments);
int plantCommand(const QStringList& arguments);
int identifyCommand(const QStringList& arguments);

}  // namespace prisca::app::cli
