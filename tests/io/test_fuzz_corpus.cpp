// Every regression input in tests/io/corpus (hostile files written by hand, and inputs the fuzzer
// once broke the loader with) and every example scene passes the fuzzer's check
// (tests/fuzz/scene_input_check.h), so a fixed crash stays fixed without running the fuzzer.

#include "tests/fuzz/scene_input_check.h"

#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QTest>

using namespace Qt::Literals::StringLiterals;

namespace {

const QString kSourceDir = QStringLiteral(SPRINGLAB_SOURCE_DIR);

// the files under a folder, recursively, as paths relative to the source tree, sorted
QStringList filesUnder(const QString &folder, const QStringList &patterns)
{
    QStringList files;
    const QDir source(kSourceDir);
    QDirIterator it(kSourceDir + u'/' + folder, patterns, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories);
    while (it.hasNext())
        files += source.relativeFilePath(it.next());
    files.sort();
    return files;
}

QStringList corpusFiles()
{
    return filesUnder(u"tests/io/corpus"_s, {});
}

}  // namespace

class TestFuzzCorpus : public QObject {
    Q_OBJECT

private slots:
    // the corpus is there, and holds at least the hostile cases written for it by hand
    void corpusHoldsTheHostileCases()
    {
        const QStringList files = corpusFiles();
        QVERIFY2(!files.isEmpty(), "tests/io/corpus is empty or missing");
        const QStringList hostile = {
            u"empty-file.json"_s,       u"truncated-in-particles.json"_s,  u"deep-nesting-5000.json"_s,
            u"nan-literal-mass.json"_s, u"infinity-literal-offset.json"_s, u"number-too-large-1e999.json"_s,
            u"negative-radius.json"_s,  u"zero-mass.json"_s,               u"substeps-int-max.json"_s,
            u"duplicate-key-mass.json"_s, u"wrong-type-name.json"_s,       u"utf8-byte-order-mark.json"_s,
            u"non-utf8-name.json"_s,    u"spring-to-missing-particle.json"_s,
        };
        for (const QString &name : hostile)
            QVERIFY2(files.contains(u"tests/io/corpus/"_s + name), qPrintable(name + u" is missing from the corpus"_s));
    }

    void inputPassesTheCheck_data()
    {
        QTest::addColumn<QString>("path");
        const QStringList files = corpusFiles() + filesUnder(u"resources/scenes"_s, {u"*.json"_s});
        for (const QString &path : files)
            QTest::newRow(qPrintable(path)) << path;
    }

    void inputPassesTheCheck()
    {
        QFETCH(QString, path);
        QFile file(kSourceDir + u'/' + path);
        QVERIFY2(file.open(QIODevice::ReadOnly), qPrintable(file.errorString()));
        const QString problem = fuzz::checkSceneInput(file.readAll());
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }
};

QTEST_APPLESS_MAIN(TestFuzzCorpus)
#include "test_fuzz_corpus.moc"
