// Figures saved as files (app/plot/FigureFile.h): the SVG well formed, PNG and SVG files written
// atomically, refused, replaced or kept as the extension, the folder and the disk allow.

#include "PlotTestSupport.h"

class TestPlotFiles : public QObject {
    Q_OBJECT
  private slots:

    void svg_isWellFormedAndCarriesTheTitle() {
        QTemporaryDir dir;
        Axes axes;
        axes.title = QStringLiteral("Panel <one>");
        axes.lines.push_back(horizontalLine(0.5, 0.0, 1.0));
        Figure figure = onePanel(axes, QSize(400, 300));
        figure.title = QStringLiteral("A figure");
        QString error;
        const QString path = dir.filePath(QStringLiteral("figure.SVG"));  // extension in any case
        QVERIFY2(saveFigure(figure, path, &error), qPrintable(error));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray text = file.readAll();
        QVERIFY(text.startsWith("<?xml"));
        QVERIFY(text.contains("viewBox=\"0 0 400 300\""));
        QVERIFY(text.contains("<title>A figure</title>"));
        QVERIFY(QSvgRenderer(path).isValid());
        // Red pixels where the PNG has them: the same drawing.
        QVERIFY(redRow(renderSvg(path, figure.size), 200) > 0);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{"figure.SVG"});
    }

    void save_refusesAnUnknownExtensionNamingThePath() {
        QTemporaryDir dir;
        const Figure figure = onePanel(Axes{}, QSize(320, 240));
        QString error;
        const QString path = dir.filePath(QStringLiteral("a.bmp"));
        QVERIFY(!saveFigure(figure, path, &error));
        QVERIFY2(error.contains(path), qPrintable(error));
        QVERIFY(!QFile::exists(path));
        QVERIFY(!saveFigure(figure, dir.filePath("no/such/dir/a.png"), &error));
        QVERIFY2(error.contains("no/such/dir/a.png"), qPrintable(error));
    }

    void save_leavesNoPartialFileWhenTheFileCannotBeReplaced() {
        // A directory stands where the figure should go: the image is written to a temporary
        // file, the replace fails, and neither the temporary nor anything else is left.
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("figure.png"));
        QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("figure.png")));
        QString error;
        QVERIFY(!saveFigure(onePanel(Axes{}, QSize(320, 240)), path, &error));
        QVERIFY2(error.contains(path), qPrintable(error));
        QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden),
                 QStringList{"figure.png"});
        QVERIFY(QFileInfo(path).isDir());
    }

    void save_inAReadOnlyDirectoryFailsAndLeavesItUntouched() {
        if (geteuid() == 0) {
            QSKIP("permissions do not bind the superuser; the test above covers a failed replace");
        }
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("a.png"));
        QFile old(path);
        QVERIFY(old.open(QIODevice::WriteOnly));
        old.write("old");
        old.close();
        QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::ExeOwner);
        QString error;
        const bool saved = saveFigure(onePanel(Axes{}, QSize(320, 240)), path, &error);
        QFile::setPermissions(dir.path(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        QVERIFY(!saved);
        QVERIFY2(error.contains(path), qPrintable(error));
        QVERIFY(old.open(QIODevice::ReadOnly));
        QCOMPARE(old.readAll(), QByteArray("old"));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"a.png"});
    }

    void save_replacesAnExistingPngAndRefusesABadSize() {
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("a.png"));
        QFile old(path);
        QVERIFY(old.open(QIODevice::WriteOnly));
        old.write("not a png");
        old.close();
        Figure figure = onePanel(Axes{}, QSize(320, 240));
        QString error;
        QVERIFY2(saveFigure(figure, path, &error), qPrintable(error));
        QCOMPARE(QImage(path).size(), QSize(320, 240));
        figure.size = QSize(0, 240);
        QVERIFY(renderFigure(figure).isNull());
        QVERIFY(!saveFigure(figure, path, &error));
        QVERIFY(error.contains(path));
        QCOMPARE(QImage(path).size(), QSize(320, 240));  // the old file is untouched
    }

    void save_onAFullDiskFailsAndKeepsTheOldFile_data() {
        QTest::addColumn<QString>("name");
        QTest::newRow("png") << "a.png";
        QTest::newRow("svg") << "a.svg";
    }

    void save_onAFullDiskFailsAndKeepsTheOldFile() {
        // A small image stays in the file's buffer until commit; its failed flush was reported
        // as saved and left an empty file.
        QFETCH(QString, name);
        QTemporaryDir dir;
        const QString path = dir.filePath(name);
        QFile old(path);
        QVERIFY(old.open(QIODevice::WriteOnly));
        old.write("old");
        old.close();
        QString error;
        {
            const FileSizeLimit full(100);
            QVERIFY(full.active());
            QVERIFY(!saveFigure(onePanel(Axes{}, QSize(320, 240)), path, &error));
        }
        QVERIFY2(error.contains(path), qPrintable(error));
        QVERIFY(old.open(QIODevice::ReadOnly));
        QCOMPARE(old.readAll(), QByteArray("old"));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{name});
    }
};

QTEST_MAIN(TestPlotFiles)
#include "test_plot_files.moc"
