#pragma once

#include <QWidget>

class QLabel;

namespace prisca::app {

/// The central panel of this early version: says plainly what PRISCA Lab does and which panels
/// are still to come. It has no controls, because nothing can be driven yet.
class WelcomePanel : public QWidget {
    Q_OBJECT
  public:
    explicit WelcomePanel(QWidget* parent = nullptr);

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void retranslateUi();

    QLabel* heading_;
    QLabel* summary_;
    QLabel* upcoming_;
    QLabel* notice_;
};

}  // namespace prisca::app
