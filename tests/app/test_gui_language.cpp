// The window in each language, driven offscreen: Help (its shortcuts and the operator guide),
// the charts' axis titles, and every visible text following a switch of language both ways.

#include "GuiWindowTestSupport.h"

class TestGuiLanguage : public QObject {
    Q_OBJECT
  private slots:
    void initTestCase() { initGuiTestCase("test_gui_language"); }
    void init() { resetGuiState(); }

    void help_listsTheShortcutsAndShowsTheOperatorGuide() {
        Window w;
        auto* shortcuts = w.find<QAction>("shortcutsAction");
        QVERIFY(shortcuts);
        const QString sheet = answerMessageBox(&w.window, [&] { shortcuts->trigger(); });
        for (const char* key : {"F5", "F6", "Shift+F5", "Ctrl+R", "Space or Esc", "Ctrl+Q",
                                "Ctrl+Shift+R", "Ctrl+O", "Ctrl+S", "F1"}) {
            QVERIFY2(sheet.contains(QLatin1String(key)), key);
        }
        w.find<QAction>("guideAction")->trigger();
        auto* guide = w.window.findChild<QDialog*>(QStringLiteral("operatorGuide"));
        QVERIFY(guide);
        auto* text = guide->findChild<QTextBrowser*>(QStringLiteral("guideText"));
        QVERIFY(text->toPlainText().contains(QLatin1String("E-STOP")));
        // The guide built in is the one in docs/ (not a stale copy).
        QFile source(QStringLiteral(PRISCA_SOURCE_DIR "/docs/operator-guide.md"));
        QVERIFY(source.open(QIODevice::ReadOnly));
        QFile built(QStringLiteral(":/docs/operator-guide.md"));
        QVERIFY(built.open(QIODevice::ReadOnly));
        const QByteArray guideText = source.readAll();
        QCOMPARE(built.readAll(), guideText);
        // Every picture it shows is built in with it and loads.
        QRegularExpressionMatchIterator pictures =
            QRegularExpression(QStringLiteral("!\\[[^\\]]*\\]\\(([^)]+\\.png)\\)"))
                .globalMatch(QString::fromUtf8(guideText));
        int shown = 0;
        while (pictures.hasNext()) {
            const QString name = pictures.next().captured(1);
            const QVariant picture = text->loadResource(QTextDocument::ImageResource, QUrl(name));
            QVERIFY2(!QImage::fromData(picture.toByteArray()).isNull(), qPrintable(name));
            ++shown;
        }
        QVERIFY(shown >= 4);
        guide->close();
    }

    void layout_at1280x800ShowsAWholeRunsResultsAndTheRigsButtons() {
        Window w;
        w.setSpeedIndex(2);
        w.find<QSpinBox>("trials")->setValue(5);
        w.find<RunPanel>("runPanel")->startRun();
        QTRY_COMPARE_WITH_TIMEOUT(w.results()->rowCount(), 5, kRunTimeoutMs);
        QTRY_COMPARE(w.window.run().phase(), RunPhase::Idle);
        // Every row of a five-trial run and the export button, without scrolling.
        QTableWidget* results = w.results();
        for (int r = 0; r < 5; ++r) {
            QVERIFY2(results->visualItemRect(results->item(r, 0)).bottom() <=
                         results->viewport()->height(),
                     qPrintable(QString::number(r)));
        }
        QVERIFY(wholeInView(results));
        QVERIFY(wholeInView(w.find<QPushButton>("exportRunLog")));
        // The rig's buttons, in view whatever page of its tabs is shown (This computer too).
        dockOf(w, "rigDock")->raise();
        for (int page = 0; page < w.find<QTabWidget>("rigTabs")->count(); ++page) {
            w.find<QTabWidget>("rigTabs")->setCurrentIndex(page);
            for (const char* name :
                 {"startCamera", "connectLink", "runOnRig", "stopOnRig", "driveOnRig"}) {
                QTRY_VERIFY2(wholeInView(w.find<QPushButton>(name)), name);
            }
            // Every page as wide as the panel: no sideways scrolling. On failure, the widgets
            // wider than the page say which.
            auto* scroll =
                qobject_cast<QScrollArea*>(w.find<QTabWidget>("rigTabs")->currentWidget());
            QVERIFY(scroll);
            const auto tooWide = [scroll] {
                QStringList wide;
                for (QWidget* child : scroll->widget()->findChildren<QWidget*>()) {
                    if (child->isVisible() &&
                        child->minimumSizeHint().width() > scroll->viewport()->width() / 2) {
                        wide << QStringLiteral("%1 %2 (%3)")
                                    .arg(QString::fromLatin1(child->metaObject()->className()),
                                         child->objectName())
                                    .arg(child->minimumSizeHint().width());
                    }
                }
                return wide.join(QStringLiteral(", "));
            };
            // Waits for the page's layout to settle after the switch, on its state.
            QTRY_VERIFY2(!scroll->horizontalScrollBar()->isVisible(),
                         qPrintable(QStringLiteral("page %1 of width %2 scrolls sideways: %3")
                                        .arg(page)
                                        .arg(scroll->viewport()->width())
                                        .arg(tooWide())));
        }
    }

    void layout_at1280x800ShowsTheWholeMappingTabAndTheNewestRunResult() {
        Window w;
        w.setSpeedIndex(2);
        w.find<QSpinBox>("trials")->setValue(6);
        w.find<RunPanel>("runPanel")->startRun();
        QTRY_COMPARE_WITH_TIMEOUT(w.results()->rowCount(), 6, kRunTimeoutMs);
        QTRY_COMPARE(w.window.run().phase(), RunPhase::Idle);
        // The Mapping tab brought up: Fit B_v, the whole fit table and its warnings in view, no
        // sideways scrolling; the Run panel keeps its newest result in view.
        dockOf(w, "mappingDock")->raise();
        auto* fit = w.find<QTableWidget>("fitResult");
        QTRY_VERIFY2(wholeInView(fit), "the fit table");
        QVERIFY(wholeInView(w.find<QPushButton>("fitButton")));
        auto* warnings = w.find<QLabel>("fitWarnings");
        QVERIFY(!warnings->isVisible() || wholeInView(warnings));
        auto* scroll = qobject_cast<QScrollArea*>(dockOf(w, "mappingDock")->widget());
        QVERIFY(scroll && !scroll->horizontalScrollBar()->isVisible());
        QTableWidget* results = w.results();
        QTRY_VERIFY(results->visualItemRect(results->item(5, 0)).bottom() <=
                    results->viewport()->height());
        QVERIFY(results->visualItemRect(results->item(5, 0)).top() >= 0);
        // Back on the Task tab, the Run panel shows the whole run again.
        dockOf(w, "taskDock")->raise();
        QTRY_VERIFY(results->visualItemRect(results->item(1, 0)).top() >= 0 &&
                    results->visualItemRect(results->item(5, 0)).bottom() <=
                        results->viewport()->height());
    }

    void chartAxisTitles_fitTheirAxesInEachLanguage() {
        Window w;
        for (const char* language : {"en", "zh_HK"}) {
            QVERIFY(w.languages.setLanguage(QString::fromLatin1(language)));
            QCoreApplication::processEvents();
            // Every chart's vertical title fits the plot's height (else QtCharts elides it to
            // a sliver), with the chart dock at its smallest.
            for (QChartView* view :
                 w.find<LiveChartsPanel>("liveChartsPanel")->findChildren<QChartView*>()) {
                view->resize(view->width(), view->minimumHeight());
                view->chart()->resize(view->size());
                for (QAbstractAxis* axis : view->chart()->axes(Qt::Vertical)) {
                    const int title =
                        QFontMetrics(axis->titleFont()).horizontalAdvance(axis->titleText());
                    QVERIFY2(title < view->chart()->plotArea().height(),
                             qPrintable(QStringLiteral("%1: \"%2\" is %3 px on a %4 px axis")
                                            .arg(QLatin1String(language), axis->titleText())
                                            .arg(title)
                                            .arg(view->chart()->plotArea().height())));
                }
            }
        }
    }

    void layout_at1280x800ShowsTableIsRowsAndEveryColumn() {
        // A Table I of every method, kept as a finished experiment is, shown at start.
        auto table = std::make_shared<prisca::sim::Table1Result>();
        table->lot = Eigen::Vector3d(4.0, 0.8, 1.2);
        for (const QString& method : prisca::sim::MethodCatalog::table1Ids()) {
            prisca::sim::MethodTrials m;
            m.method = method;
            for (int t = 0; t < 3; ++t) {
                prisca::sim::TrialSummary trial;
                trial.finalPositionError = 0.1234 + 0.01 * t;
                trial.finalHeadingError = 0.2345 + 0.01 * t;
                m.trials.push_back(trial);
                m.completed.push_back(true);
            }
            table->methods.push_back(m);
        }
        KeptExperiment kept;
        kept.record.plant = QStringLiteral("slidecar");
        kept.record.count = 3;
        kept.record.seed = 1;
        kept.record.demonstration = QStringLiteral("a test");
        kept.record.finished = QDateTime::currentDateTime();
        kept.table1 = table;
        QString error;
        QVERIFY2(saveKeptExperiment(keptExperimentPath(), kept, &error), qPrintable(error));
        Window w;
        dockOf(w, "experimentsDock")->raise();
        auto* results = w.find<QTableWidget>("experimentTable");
        QTRY_VERIFY(results->isVisible());
        QCOMPARE(results->rowCount(), static_cast<int>(table->methods.size()));
        // Five rows and every column without scrolling, the controls and exports in view.
        QVERIFY(wholeInView(results));
        for (int r = 0; r < 5; ++r) {
            QVERIFY2(results->visualItemRect(results->item(r, 0)).bottom() <=
                         results->viewport()->height(),
                     qPrintable(QString::number(r)));
        }
        QTRY_VERIFY(!results->horizontalScrollBar()->isVisible());
        for (const char* name :
             {"startExperiment", "cancelExperiment", "exportTable", "exportFigure"}) {
            QVERIFY2(wholeInView(w.find<QWidget>(name)), name);
        }
        QVERIFY(wholeInView(w.find<QWidget>("experimentCount")));
        QVERIFY(!w.find<QLabel>("experimentFigure")->pixmap().isNull());
    }

    void language_everyVisibleTextFollowsASwitchBothWays() {
        Window w;
        // Some dynamic text first: a finished run's rows, a status, a Table I result.
        w.setSpeedIndex(2);
        w.find<QSpinBox>("trials")->setValue(1);
        w.find<RunPanel>("runPanel")->startRun();
        QTRY_COMPARE_WITH_TIMEOUT(w.window.run().phase(), RunPhase::Idle, kRunTimeoutMs);
        QTRY_COMPARE(w.results()->rowCount(), 1);
        w.find<RunPanel>("runPanel")->emergencyAction()->trigger();
        QTRY_COMPARE(w.window.run().phase(), RunPhase::EmergencyStopped);
        w.find<RunPanel>("runPanel")->resetEmergencyAction()->trigger();
        QTRY_VERIFY(w.find<QLabel>("runStatus")->text().contains(QLatin1String("reset")));
        w.find<QComboBox>("experimentKind")->setCurrentIndex(0);
        w.find<QSpinBox>("experimentCount")->setValue(1);
        auto* experiments = w.find<ExperimentsPanel>("experimentsPanel");
        experiments->start();
        QTRY_VERIFY_WITH_TIMEOUT(!experiments->isRunning(), 240000);
        auto* job = w.find<QLabel>("jobStatus");
        QTRY_COMPARE(job->text(), QStringLiteral("Job: none"));  // the status bar has caught up
        const QMap<QString, QString> english = visibleTexts(&w.window);

        QVERIFY(w.languages.setLanguage(QStringLiteral("zh_HK")));
        QTRY_COMPARE(job->text(), QStringLiteral("工作：無"));  // the switch has reached the window
        const QMap<QString, QString> chinese = visibleTexts(&w.window);
        // Texts with English words left after the switch (names and units aside).
        static const QRegularExpression word(QStringLiteral("[A-Za-z]{4,}"));
        static const QSet<QString> names = {QStringLiteral("PRISCA"),  QStringLiteral("PGSD"),
                                            QStringLiteral("PEGASUS"), QStringLiteral("STOP"),
                                            QStringLiteral("CRSF"),    QStringLiteral("SBUS"),
                                            QStringLiteral("LATCHED"), QStringLiteral("V4L2")};
        // Kept as they are in every language, by design: the methods' labels (Table I's row
        // names, as in the paper), a parameter's choices (its --param values), the plant's
        // control names (the demonstration file's columns), each language's own name, ports.
        QSet<QString> asIs;
        for (const QString& id : prisca::sim::MethodCatalog::ids()) {
            asIs.insert(prisca::sim::MethodCatalog::get(id).label);
        }
        for (const prisca::sim::MethodParameter* parameter :
             prisca::sim::MethodCatalog::parameters()) {
            for (const char* choice : parameter->choices) {
                asIs.insert(QString::fromLatin1(choice));
            }
        }
        for (const QString& name : w.window.session().profile().info.actionNames) {
            asIs.insert(name);
        }
        QStringList english_left;
        for (auto it = chinese.begin(); it != chinese.end(); ++it) {
            if (it.value() != english.value(it.key())) {
                continue;  // translated
            }
            if (asIs.contains(it.value()) || it.key().contains(QLatin1String("languageAction_")) ||
                it.value().startsWith(QLatin1String("/dev/")) ||
                it.value() == it.value().toUpper()) {  // a protocol's name: CRSF, MULTIPROTOCOL
                continue;
            }
            auto match = word.globalMatch(it.value());
            while (match.hasNext()) {
                const QString w = match.next().captured();
                if (!names.contains(w.toUpper()) && !names.contains(w)) {
                    english_left << it.key().section(QLatin1Char('@'), 0, 0) +
                                        QStringLiteral(" = ") + it.value().left(80);
                    break;
                }
            }
        }
        // Back to English: every text is the one it was.
        QVERIFY(w.languages.setLanguage(QStringLiteral("en")));
        QTRY_COMPARE(job->text(), QStringLiteral("Job: none"));
        const QMap<QString, QString> back = visibleTexts(&w.window);
        QStringList changed;
        for (auto it = english.begin(); it != english.end(); ++it) {
            if (back.value(it.key()) != it.value()) {
                changed << it.key().section(QLatin1Char('@'), 0, 0) + QStringLiteral(": '") +
                               it.value().left(60) + QStringLiteral("' -> '") +
                               back.value(it.key()).left(60) + QLatin1Char('\'');
            }
        }
        QVERIFY2(changed.isEmpty(), qPrintable(changed.join(QLatin1Char('\n'))));
        for (const QString& left : english_left) {
            qInfo("left in English: %s", qPrintable(left));
        }
        QVERIFY2(english_left.isEmpty(), qPrintable(english_left.join(QLatin1Char('\n'))));
    }
};

QTEST_MAIN(TestGuiLanguage)
#include "test_gui_language.moc"
