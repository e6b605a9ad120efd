#include "app/LanguageSwitcher.h"

#include <QCoreApplication>
#include <QLocale>
#include <QLoggingCategory>
#include <QSettings>

#include <algorithm>

namespace prisca::app {

namespace {

Q_LOGGING_CATEGORY(lcLanguage, "prisca.app.language")

bool isOffered(const QString& code) {
    const QList<UiLanguage> languages = LanguageSwitcher::availableLanguages();
    return std::any_of(languages.cbegin(), languages.cend(),
                       [&code](const UiLanguage& language) { return language.code == code; });
}

}  // namespace

LanguageSwitcher::LanguageSwitcher(QObject* parent) : QObject(parent) {}

LanguageSwitcher::~LanguageSwitcher() {
    if (translator_) {
        QCoreApplication::removeTranslator(translator_.get());
    }
}

QList<UiLanguage> LanguageSwitcher::availableLanguages() {
    // Names stay in their own language so an operator can find theirs whatever is shown now.
    return {
        {QString::fromLatin1(kSourceLanguage), QStringLiteral("English")},
        {QStringLiteral("zh_HK"), QStringLiteral("繁體中文 (香港)")},
    };
}

bool LanguageSwitcher::setLanguage(const QString& code) {
    if (!apply(code)) {
        return false;
    }
    QSettings().setValue(QLatin1String(kSettingsKey), code);
    return true;
}

void LanguageSwitcher::restoreLanguage() {
    const QString stored = QSettings().value(QLatin1String(kSettingsKey)).toString();
    if (!stored.isEmpty() && apply(stored)) {
        return;
    }
    // No usable choice yet: follow the desktop's language when we have a translation for it.
    const QList<UiLanguage> languages = availableLanguages();
    for (const QString& name : QLocale::system().uiLanguages()) {
        const QLocale wanted(name);
        for (const UiLanguage& language : languages) {
            const QLocale offered(language.code);
            if (offered.language() == wanted.language() && offered.script() == wanted.script()) {
                apply(language.code);
                return;
            }
        }
    }
    apply(QString::fromLatin1(kSourceLanguage));
}

bool LanguageSwitcher::apply(const QString& code) {
    if (!isOffered(code)) {
        qCWarning(lcLanguage) << "language not offered:" << code;
        return false;
    }
    if (code == current_) {
        return true;
    }
    std::unique_ptr<QTranslator> next;
    if (code != QLatin1String(kSourceLanguage)) {
        // Load before removing the old translation so a failed load leaves the UI readable.
        next = std::make_unique<QTranslator>();
        const QString file = QStringLiteral(":/i18n/prisca_%1.qm").arg(code);
        if (!next->load(file)) {
            qCWarning(lcLanguage) << "cannot load translation" << file;
            return false;
        }
    }
    if (translator_) {
        QCoreApplication::removeTranslator(translator_.get());
    }
    translator_ = std::move(next);
    if (translator_) {
        QCoreApplication::installTranslator(translator_.get());
    }
    current_ = code;
    qCInfo(lcLanguage) << "interface language" << code;
    emit languageChanged(code);
    return true;
}

}  // namespace prisca::app
