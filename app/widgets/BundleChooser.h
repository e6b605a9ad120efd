#pragma once

#include <QDateTime>
#include <QDialog>
#include <QString>
#include <QStringList>

#include <vector>

class QTreeWidget;
class QTreeWidgetItem;

namespace prisca::app {

/// One trial bundle as the chooser lists it, read from its bundle.json only.
struct BundleEntry {
    QString folder;
    bool rig = false;  ///< a trial on the rig (else a simulated one)
    QDateTime when;    ///< started (the header's, else the folder's time)
    QString method;
    int trial = 0;
    bool complete = false;  ///< the writer wrote its result
    QString outcome;        ///< "parked 3.2 cm", "failsafe: ...", "stopped", ...
};

/// File > Replay a trial bundle: the bundles under the trial folders, newest first, the rig's
/// trials apart from the simulated ones (the simulation writes one a trial, so they would bury
/// the rig's), each with its time, method, trial and outcome; "Other folder..." opens any
/// folder. Runs through ModalDialog (never blocks E-STOP).
class BundleChooser : public QDialog {
    Q_OBJECT
  public:
    /// Lists the bundles under each of `parents` (missing folders are skipped).
    explicit BundleChooser(const QStringList& parents, QWidget* parent = nullptr);
    /// The folder chosen (empty: none).
    const QString& chosen() const { return chosen_; }
    /// The bundles under `parents`, newest first (rig and simulation mixed; scan() reads only
    /// each bundle.json).
    static std::vector<BundleEntry> scan(const QStringList& parents);

  private:
    void choose(QTreeWidgetItem* item);

    QTreeWidget* list_;
    QString chosen_;
};

}  // namespace prisca::app
