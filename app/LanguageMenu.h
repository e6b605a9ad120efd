#pragma once

#include <QMenu>

class QActionGroup;

namespace prisca::app {

class LanguageSwitcher;

/// View > Language: one checkable entry per offered language, kept in step with the switcher.
/// Choosing an entry switches the interface at once and remembers the choice.
class LanguageMenu : public QMenu {
    Q_OBJECT
  public:
    /// `switcher` must outlive the menu.
    explicit LanguageMenu(LanguageSwitcher& switcher, QWidget* parent = nullptr);

  protected:
    void changeEvent(QEvent* event) override;

  private:
    void retranslateUi();
    void markCurrent(const QString& code);

    LanguageSwitcher& switcher_;
    QActionGroup* group_;
};

}  // namespace prisca::app
