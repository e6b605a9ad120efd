// Every translation is finished: no empty, unfinished, obsolete or vanished message in any .ts,
// and no tr() string in the application that the .ts files do not know yet.
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>

#include <algorithm>

namespace {

struct TsMessage {
    QString context;
    QString source;
    QString type;       ///< The translation's type attribute: "", "unfinished", ...
    QStringList forms;  ///< The translation, or its plural forms.
    bool hasTranslation = false;
};

QSet<QString> placeholders(const QString& text) {
    static const QRegularExpression pattern(QStringLiteral("%(\\d{1,2}|n)"));
    QSet<QString> found;
    for (const QRegularExpressionMatch& m : pattern.globalMatch(text)) {
        found.insert(m.captured(0));
    }
    return found;
}

// A menu mnemonic: '&' followed by something other than another '&' or a space.
bool hasMnemonic(const QString& text) {
    static const QRegularExpression pattern(QStringLiteral("(^|[^&])&[^&\\s]"));
    return pattern.match(text).hasMatch();
}

QList<TsMessage> readMessages(const QString& path, QString* language, QString* error) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = file.errorString();
        return {};
    }
    QList<TsMessage> messages;
    QString context;
    QXmlStreamReader xml(&file);
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement) {
            continue;
        }
        const QStringView name = xml.name();
        if (name == u"TS") {
            *language = xml.attributes().value(QStringLiteral("language")).toString();
        } else if (name == u"context") {
            context.clear();
        } else if (name == u"name") {
            context = xml.readElementText();
        } else if (name == u"message") {
            messages.append(TsMessage{context, {}, {}, {}, false});
        } else if (name == u"source" && !messages.isEmpty()) {
            messages.last().source = xml.readElementText();
        } else if (name == u"translation" && !messages.isEmpty()) {
            TsMessage& message = messages.last();
            message.hasTranslation = true;
            message.type = xml.attributes().value(QStringLiteral("type")).toString();
            QString plain;
            // Either plain text or <numerusform> children, one per plural form.
            while (xml.readNext() != QXmlStreamReader::EndElement || xml.name() != u"translation") {
                if (xml.hasError()) {
                    break;
                }
                if (xml.isCharacters()) {
                    plain += xml.text();
                } else if (xml.isStartElement() && xml.name() == u"numerusform") {
                    message.forms << xml.readElementText();
                }
            }
            if (message.forms.isEmpty()) {
                message.forms << plain;
            }
        }
    }
    if (xml.hasError()) {
        *error = QStringLiteral("line %1, column %2: %3")
                     .arg(xml.lineNumber())
                     .arg(xml.columnNumber())
                     .arg(xml.errorString());
    }
    return messages;
}

// One line per problem: file, context, source text and what is wrong.
QStringList problemsIn(const QString& path) {
    const QString fileName = QFileInfo(path).fileName();
    QString language;
    QString error;
    const QList<TsMessage> messages = readMessages(path, &language, &error);
    if (!error.isEmpty()) {
        return {QStringLiteral("%1: unreadable: %2").arg(fileName, error)};
    }
    QStringList problems;
    const QString expectedLanguage = QFileInfo(path).completeBaseName().section(u'_', 1);
    if (language != expectedLanguage) {
        problems << QStringLiteral("%1: language attribute '%2', file name says '%3'")
                        .arg(fileName, language, expectedLanguage);
    }
    if (messages.isEmpty()) {
        problems << QStringLiteral("%1: no messages").arg(fileName);
    }
    for (const TsMessage& message : messages) {
        QStringList reasons;
        if (!message.type.isEmpty()) {
            reasons << QStringLiteral("type=\"%1\"").arg(message.type);
        }
        const bool empty =
            !message.hasTranslation ||
            std::any_of(message.forms.cbegin(), message.forms.cend(),
                        [](const QString& form) { return form.trimmed().isEmpty(); });
        if (empty) {
            reasons << QStringLiteral("empty translation");
        }
        for (const QString& form : message.forms) {
            if (!form.trimmed().isEmpty() && placeholders(form) != placeholders(message.source)) {
                reasons << QStringLiteral("placeholders differ in '%1'").arg(form);
            }
            if (!form.trimmed().isEmpty() && hasMnemonic(message.source) && !hasMnemonic(form)) {
                reasons << QStringLiteral("menu mnemonic (&) missing in '%1'").arg(form);
            }
        }
        if (!reasons.isEmpty()) {
            problems << QStringLiteral("%1: [%2] \"%3\": %4")
                            .arg(fileName, message.context, message.source,
                                 reasons.join(QStringLiteral(", ")));
        }
    }
    return problems;
}

QStringList tsFiles() {
    const QDir dir(QStringLiteral(PRISCA_TRANSLATIONS_DIR));
    QStringList paths;
    for (const QString& name : dir.entryList({QStringLiteral("*.ts")}, QDir::Files, QDir::Name)) {
        paths << dir.filePath(name);
    }
    return paths;
}

// Every source under app/ and the few outside it: the set app/CMakeLists.txt hands to lupdate.
QStringList appSources() {
    QStringList sources;
    QDirIterator it(QStringLiteral(PRISCA_SOURCE_DIR "/app"), {"*.cpp", "*.h"}, QDir::Files,
                    QDirIterator::Subdirectories);
    while (it.hasNext()) {
        sources << it.next();
    }
    sources.sort();
    sources << QStringLiteral(PRISCA_SOURCE_DIR "/sim/PlantCatalog.cpp");  // the plants' names
    for (const char* family : {"FeedbackMethods", "LearningMethods", "LqrMethod", "PlanningMethods",
                               "PriscaMethods"}) {  // method parameters
        sources
            << QStringLiteral(PRISCA_SOURCE_DIR "/sim/methods/%1.cpp").arg(QLatin1String(family));
    }
    sources << QStringLiteral(PRISCA_SOURCE_DIR "/rig/RigSession.cpp");        // the rig's messages
    sources << QStringLiteral(PRISCA_SOURCE_DIR "/rig/RigSessionTrials.cpp");  // and its trials'
    sources << QStringLiteral(PRISCA_SOURCE_DIR "/rig/PreTrialCheck.cpp");   // the pre-trial check
    sources << QStringLiteral(PRISCA_SOURCE_DIR "/rig/RigCalibration.cpp");  // the set-up
    sources << QStringLiteral(PRISCA_SOURCE_DIR "/rig/RigDoctor.cpp");       // doctor's lines
    sources << QStringLiteral(PRISCA_SOURCE_DIR "/core/ActionMapping.cpp");  // the fit's warnings
    sources << QStringLiteral(PRISCA_SOURCE_DIR
                              "/devices/TransmitterLink.cpp");  // failsafe reasons
    return sources;
}

}  // namespace

class TestTranslationsComplete : public QObject {
    Q_OBJECT
  private slots:
    void translationsDir_holdsHongKongChinese();
    void tsFile_hasNoUnfinishedMessage_data();
    void tsFile_hasNoUnfinishedMessage();
    void appSources_haveNoStringMissingFromTheTsFiles_data();
    void appSources_haveNoStringMissingFromTheTsFiles();
};

void TestTranslationsComplete::translationsDir_holdsHongKongChinese() {
    QVERIFY2(QFileInfo::exists(QStringLiteral(PRISCA_TRANSLATIONS_DIR "/prisca_zh_HK.ts")),
             "translations/prisca_zh_HK.ts is missing");
}

void TestTranslationsComplete::tsFile_hasNoUnfinishedMessage_data() {
    QTest::addColumn<QString>("path");
    for (const QString& path : tsFiles()) {
        QTest::newRow(qPrintable(QFileInfo(path).fileName())) << path;
    }
}

void TestTranslationsComplete::tsFile_hasNoUnfinishedMessage() {
    QFETCH(QString, path);
    const QStringList problems = problemsIn(path);
    QVERIFY2(problems.isEmpty(), qPrintable(QStringLiteral("\n") + problems.join(u'\n')));
}

void TestTranslationsComplete::appSources_haveNoStringMissingFromTheTsFiles_data() {
    tsFile_hasNoUnfinishedMessage_data();
}

void TestTranslationsComplete::appSources_haveNoStringMissingFromTheTsFiles() {
    QFETCH(QString, path);
    // lupdate on a scratch copy: a new tr() string comes out "unfinished", a string gone from
    // the code "vanished". The fix for either is the update_translations target, then translate.
    QTemporaryDir scratch;
    QVERIFY(scratch.isValid());
    const QString copy = scratch.filePath(QFileInfo(path).fileName());
    QVERIFY(QFile::copy(path, copy));
    QFile::setPermissions(copy, QFile::ReadOwner | QFile::WriteOwner);

    QProcess lupdate;
    QStringList arguments{QStringLiteral("-silent"), QStringLiteral("-I"),
                          QStringLiteral(PRISCA_SOURCE_DIR)};
    arguments << appSources() << QStringLiteral("-ts") << copy;
    lupdate.start(QStringLiteral(PRISCA_LUPDATE), arguments);
    QVERIFY2(lupdate.waitForFinished(60000), qPrintable(lupdate.errorString()));
    QVERIFY2(lupdate.exitStatus() == QProcess::NormalExit && lupdate.exitCode() == 0,
             lupdate.readAllStandardError().constData());

    const QStringList problems = problemsIn(copy);
    QVERIFY2(problems.isEmpty(),
             qPrintable(QStringLiteral("\nrun `cmake --build <build> --target update_translations`"
                                       " and translate:\n") +
                        problems.join(u'\n')));
}

QTEST_GUILESS_MAIN(TestTranslationsComplete)
#include "test_translations_complete.moc"
