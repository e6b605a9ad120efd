#include "app/cli/CommandTable.h"

#include "app/cli/Commands.h"

#include <algorithm>

namespace prisca::app::cli {

const std::vector<CliCommand>& commandTable() {
    // A command is wired in by replacing its nullptr with the function from its own file.
    static const std::vector<CliCommand> table = {
        {"simulate", "Simulate a plant from an initial state under given actions", simulateCommand},
        {"demo", "Generate a scripted demonstration for a plant", demoCommand},
        {"fit", "Fit the action mapping B_v to a demonstration (eq. 8)", fitCommand},
        {"methods", "List the methods and their parameters (units, ranges, defaults)",
         methodsCommand},
        {"plant", "A plant's physical parameters: print them, write a plant file, check one",
         plantCommand},
        {"identify", "Fit a plant's parameters to a demonstration and trials (a plant file)",
         identifyCommand},
        {"run", "Run PRISCA or a baseline on a plant and log the trial", runCommand},
        {"table1", "Run batches of trials and report the paper's Table I metrics", table1Command},
        {"curve", "Learning curves of several methods over many runs", curveCommand},
        {"lemma41", "The H-gamma grid of Lemma 4.1 (Fig. 2)", lemma41Command},
        {"calibrate-camera", "Fit the camera's lens (intrinsics, distortion) to chessboard views",
         calibrateCameraCommand},
        {"calibrate-floor", "Fit the floor calibration to measured points, through the lens",
         calibrateFloorCommand},
        {"track", "Track the car's IR LEDs in a video and write its poses", trackCommand},
        {"link", "Send channel values to a transmitter over a serial link", linkCommand},
        {"rig", "Trials on the virtual rig: camera, tracker, controller, link and car, headless",
         rigCommand},
        {"replay", "A trial bundle's summary and scores", replayCommand},
        {"doctor", "Check this computer for the rig: ports, permissions, cameras, files, disk",
         doctorCommand},
    };
    return table;
}

const CliCommand* findCommand(QStringView name) {
    const std::vector<CliCommand>& table = commandTable();
    const auto found = std::find_if(table.cbegin(), table.cend(), [name](const CliCommand& c) {
        return name == QLatin1String(c.name);
    });
    return found == table.cend() ? nullptr : &*found;
}

}  // namespace prisca::app::cli
