// The plot's drawing: a curve of many more samples than pixels still shows a spike of a single
// sample (each pixel column keeps its lowest and highest value), and a canvas with no samples
// says what to do instead of drawing axes.

#include "ui/panels/plot_canvas.h"
#include "ui/panels/plot_series.h"

#include <QImage>
#include <QPixmap>
#include <QtTest>

namespace {

// reddish, as the first curve's colour is, also where antialiasing blends it
bool reddish(QRgb pixel)
{
    return qRed(pixel) > 150 && qGreen(pixel) < 130 && qBlue(pixel) < 130;
}

// reddish pixels in the middle of the canvas's upper half, below the legend
int reddishInUpperMiddle(const QImage &image)
{
    int found = 0;
    for (int y = image.height() / 5; y < image.height() / 2; ++y)
        for (int x = image.width() * 3 / 10; x < image.width() * 7 / 10; ++x)
            found += reddish(image.pixel(x, y)) ? 1 : 0;
    return found;
}

}  // namespace

class TestPlotCanvas : public QObject {
    Q_OBJECT

private slots:
    void aSpikeOfOneSampleSurvivesCrowding_data();
    void aSpikeOfOneSampleSurvivesCrowding();
    void noSamplesShowsTheEmptyText();
};

void TestPlotCanvas::aSpikeOfOneSampleSurvivesCrowding_data()
{
    QTest::addColumn<bool>("spike");
    QTest::addColumn<int>("reddish");
    QTest::newRow("spike") << true << 1;
    QTest::newRow("flat") << false << 0;
}

void TestPlotCanvas::aSpikeOfOneSampleSurvivesCrowding()
{
    QFETCH(bool, spike);
    QFETCH(int, reddish);

    // 20000 samples on a canvas 600 px wide: zero, but for one sample in the middle at 1 (and a
    // second, flat curve, so that the range is the same without the spike)
    ui::PlotSeries series({{"spiky", "J"}, {"flat", "J"}});
    for (std::uint64_t s = 0; s < 20000; ++s)
        series.add(s, 0.01 * double(s), {spike && s == 10001 ? 1.0 : 0.0, s == 0 ? 1.0 : 0.0});
    ui::PlotCanvas canvas;
    canvas.setSeries(&series);
    canvas.resize(600, 240);
    const QImage image = canvas.grab().toImage();
    QCOMPARE(image.size(), QSize(600, 240) * canvas.devicePixelRatio());

    // the spike reaches up past the middle of the plot, where the flat curve never goes
    const int found = reddishInUpperMiddle(image);
    QVERIFY2(reddish ? found > 0 : found == 0, qPrintable(QString::number(found)));
}

void TestPlotCanvas::noSamplesShowsTheEmptyText()
{
    ui::PlotSeries series(std::vector<ui::PlotCurve>{{"x", "m"}});
    ui::PlotCanvas canvas;
    canvas.setSeries(&series);
    canvas.setEmptyText(QStringLiteral("Select a particle"));
    canvas.resize(300, 150);
    const QImage empty = canvas.grab().toImage();

    // no frame, no ticks: only the text, in the middle
    series.add(0, 0.0, {0.5});
    series.add(1, 0.1, {0.7});
    const QImage drawn = canvas.grab().toImage();
    int darkEmpty = 0, darkDrawn = 0;
    for (int y = 0; y < empty.height(); ++y)
        for (int x = 0; x < empty.width(); ++x) {
            darkEmpty += qGray(empty.pixel(x, y)) < 128 ? 1 : 0;
            darkDrawn += qGray(drawn.pixel(x, y)) < 128 ? 1 : 0;
        }
    QVERIFY(darkEmpty > 0);
    QVERIFY2(darkDrawn > 2 * darkEmpty, qPrintable(QStringLiteral("%1 vs %2").arg(darkDrawn).arg(darkEmpty)));
    QCOMPARE(canvas.emptyText(), QStringLiteral("Select a particle"));
}

QTEST_MAIN(TestPlotCanvas)
#include "test_plot_canvas.moc"
