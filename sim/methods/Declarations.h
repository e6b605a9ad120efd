#pragma once

// The catalog's methods, declared one family to a file in this folder: each file holds its
// methods' parameters (name, range, help, where the value lives in MethodTuning) and how each
// method is made from a tuning and a demonstration. MethodCatalog.cpp lists them in Table I's
// order and answers the queries. Internal to prisca_sim: the rest of the product reaches a
// method through MethodCatalog.

#include "sim/planning/OracleController.h"
#include "sim/tuning/MethodSpec.h"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace prisca::sim::methods {

using Mode = core::MatchingParameters::Mode;
using Made = std::unique_ptr<core::Controller>;
using Kind = MethodParameter::Kind;

// ---- Building blocks of a declaration (Declarations.cpp) ---------------------------------------
Eigen::VectorXd one(double v);
MethodParameter integer(const char* name, const char* label, const char* unit, double low,
                        double high, const char* help);
MethodParameter real(const char* name, const char* label, const char* unit, double low, double high,
                     int decimals, const char* help);
MethodParameter onOff(const char* name, const char* label, const char* help);
MethodSpec entry(const char* id, const char* label, MethodSpec::Create create);

// ---- The feedback law, shared by every method that starts from it (FeedbackMethods.cpp) --------
const MethodParameter& start();
const MethodParameter& matchingWindow();
const MethodParameter& pdKp();
const MethodParameter& pdKd();
const MethodParameter& pdHorizon();
const MethodParameter& feedbackExplainedOnly();
const MethodParameter& feedbackReverseAware();
/// Per demonstration sample: 1 where the robust fit explains it, else 0.
std::vector<double> explainedGate(const MethodTuning& profile,
                                  const core::Demonstration& demonstration);
/// Per demonstration sample, -1 on a car's heading and yaw-rate errors where it drives
/// backwards, else 1 (n x T); empty for other plants or when switched off.
Eigen::MatrixXd reverseSchedule(const MethodTuning& profile,
                                const core::Demonstration& demonstration);

// ---- The planner for a demonstration's trials (PlanningMethods.cpp) ----------------------------
OracleParameters plannerFor(const MethodTuning& profile, const core::Demonstration& demonstration);

// ---- The methods, each with its declarations ----------------------------------------------------
MethodSpec priscaMethod();                  // PriscaMethods.cpp
MethodSpec priscaPaperMethod();             // PriscaMethods.cpp
std::vector<MethodSpec> pdFamilyMethods();  // FeedbackMethods.cpp
/// "pd-lsd" made as the catalog makes it, for a method that falls back on it (FeedbackMethods.cpp).
Made makePdLsd(const MethodInput& in);
MethodSpec playbackMethod();  // FeedbackMethods.cpp
MethodSpec lqrMethod();       // LqrMethod.cpp
MethodSpec pgsdMethod();      // LearningMethods.cpp
MethodSpec pegasusMethod();   // LearningMethods.cpp
MethodSpec ilcMethod();       // LearningMethods.cpp
MethodSpec mpcMethod();       // PlanningMethods.cpp
MethodSpec oracleMethod();    // PlanningMethods.cpp

}  // namespace prisca::sim::methods
