#pragma once

#include <QList>
#include <QObject>
#include <QString>
#include <QTranslator>

#include <memory>

namespace prisca::app {

/// One language the user interface can be shown in.
struct UiLanguage {
    QString code;        ///< Locale code, e.g. "en" or "zh_HK"; also names the .qm file.
    QString nativeName;  ///< The language's name in itself, as the Language menu shows it.
};

/// Installs the application's translation for the chosen language and remembers the choice.
///
/// Switching at run time relies on Qt's LanguageChange event: every widget that shows text
/// re-reads its strings in changeEvent(). Create after QApplication and use from the GUI
/// thread only. Translations are embedded as ":/i18n/prisca_<code>.qm".
class LanguageSwitcher : public QObject {
    Q_OBJECT
  public:
    /// The language of the source strings; it needs no translation file.
    static constexpr const char* kSourceLanguage = "en";
    /// QSettings key that holds the operator's choice.
    static constexpr const char* kSettingsKey = "ui/language";

    explicit LanguageSwitcher(QObject* parent = nullptr);
    ~LanguageSwitcher() override;

    /// The languages offered, source language first.
    static QList<UiLanguage> availableLanguages();

    /// Code of the language shown now.
    QString currentLanguage() const { return current_; }

    /// Shows the interface in `code` and stores the choice in QSettings. Returns false, and
    /// keeps the current language, when `code` is not offered or its translation fails to load.
    bool setLanguage(const QString& code);

    /// Applies the stored choice; without one, the first offered language among the system's
    /// UI languages, else the source language. Nothing is stored.
    void restoreLanguage();

  signals:
    /// Emitted after a switch, once the new translation is installed.
    void languageChanged(const QString& code);

  private:
    bool apply(const QString& code);

    std::unique_ptr<QTranslator> translator_;  ///< Installed translation; null for the source.
    QString current_ = QString::fromLatin1(kSourceLanguage);
};

}  // namespace prisca::app
