#pragma once

// MainWindow's constants, shared by its sources: MainWindow.cpp (the panels, the layout, the
// session, the language), MainWindowMenus.cpp (the tool bar, the status bar, the menus, Help's
// windows, the E-STOP inputs) and MainWindowQuit.cpp (the work under way, stopping it, quitting).

#include <QSize>
#include <QString>

namespace prisca::app {

// The product name is a proper noun and stays untranslated in every language.
inline const QString kProductName = QStringLiteral("PRISCA Lab");
inline const QSize kDefaultSize(1280, 800);  // px, used until the operator has sized the window
inline const QSize kFrameAllowance(16, 48);  // px, a window manager's borders and title bar
inline constexpr int kStatusMessageMs = 4000;
inline constexpr int kNoticeMs = 15000;  // what the operator must read, e.g. replaced parameters
inline constexpr int kMaxRecent = 8;
inline const char* const kRecentKey = "session/recent";
// The session as it was at the last close.
inline const char* const kLastSessionKey = "session/last";
// The operator has dragged a separator between docks (then their sizes are theirs).
inline const char* const kOperatorSizedKey = "mainWindow/operatorSizedDocks";

}  // namespace prisca::app
