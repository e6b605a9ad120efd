#include "app/LanguageMenu.h"

#include "app/LanguageSwitcher.h"

#include <QActionGroup>
#include <QEvent>

namespace prisca::app {

LanguageMenu::LanguageMenu(LanguageSwitcher& switcher, QWidget* parent)
    : QMenu(parent), switcher_(switcher), group_(new QActionGroup(this)) {
    setObjectName(QStringLiteral("languageMenu"));
    group_->setExclusive(true);
    for (const UiLanguage& language : LanguageSwitcher::availableLanguages()) {
        QAction* action = addAction(language.nativeName);
        action->setObjectName(QStringLiteral("languageAction_") + language.code);
        action->setData(language.code);
        action->setCheckable(true);
        group_->addAction(action);
    }
    connect(group_, &QActionGroup::triggered, this, [this](QAction* action) {
        // A failed switch leaves the old language in place; put the check mark back on it.
        if (!switcher_.setLanguage(action->data().toString())) {
            markCurrent(switcher_.currentLanguage());
        }
    });
    connect(&switcher_, &LanguageSwitcher::languageChanged, this, &LanguageMenu::markCurrent);
    markCurrent(switcher_.currentLanguage());
    retranslateUi();
}

void LanguageMenu::changeEvent(QEvent* event) {
    if (event->type() == QEvent::LanguageChange) {
        retranslateUi();
    }
    QMenu::changeEvent(event);
}

void LanguageMenu::retranslateUi() {
    setTitle(tr("&Language"));
}

void LanguageMenu::markCurrent(const QString& code) {
    for (QAction* action : group_->actions()) {
        action->setChecked(action->data().toString() == code);
    }
}

}  // namespace prisca::app
