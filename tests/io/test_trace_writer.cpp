// Trace files: the header springlab-sim --trace and the editor's File › Export › Trace CSV share;
// rows from a State read back as the same doubles, rows from a Snapshot as the same floats; a
// snapshot without velocities writes zeros; a file that cannot be written says so.

#include "core/io/trace_writer.h"
#include "trace_read.h"

#include <QTemporaryDir>
#include <QTest>


using namespace Qt::Literals::StringLiterals;

using test::parseNumber;
using test::readTraceRows;

class TestTraceWriter : public QObject {
    Q_OBJECT

private slots:
    void stateRowsReadBackAsTheSameDoubles();
    void snapshotRowsReadBackAsTheSameFloats();
    void snapshotWithoutVelocitiesWritesZeros();
    void unwritableFileIsNamed();

private:
    QTemporaryDir m_dir;
};

void TestTraceWriter::stateRowsReadBackAsTheSameDoubles()
{
    core::State state;
    state.step = 7;
    state.time = 0.1 + 0.2;
    state.position = Eigen::Matrix3Xd(3, 2);
    state.position << 1.0 / 3.0, -2.5, 1e-300, 4.0, 5.0, -6.0;
    state.velocity = -state.position;
    io::TraceWriter trace;
    const QString path = m_dir.filePath(u"state.csv"_s);
    QCOMPARE(trace.open(path), QString());
    trace.writeRows(state);
    QCOMPARE(trace.close(), QString());
    QCOMPARE(trace.rowCount(), std::uint64_t(2));

    QByteArray header;
    const auto rows = readTraceRows(path, &header);
    QCOMPARE(header, QByteArray(io::kTraceHeader));
    QCOMPARE(header, QByteArray("step,time,particle,x,y,z,vx,vy,vz"));
    QCOMPARE(rows.size(), 2);
    for (int i = 0; i < 2; ++i) {
        QCOMPARE(rows[i][0], QByteArray("7"));
        QCOMPARE(parseNumber<double>(rows[i][1]), state.time);
        QCOMPARE(rows[i][2].toInt(), i);
        for (int axis = 0; axis < 3; ++axis) {
            QCOMPARE(parseNumber<double>(rows[i][3 + axis]), state.position(axis, i));
            QCOMPARE(parseNumber<double>(rows[i][6 + axis]), state.velocity(axis, i));
        }
    }
}

void TestTraceWriter::snapshotRowsReadBackAsTheSameFloats()
{
    core::Snapshot snapshot;
    snapshot.step = 12;
    snapshot.time = 0.06;
    snapshot.positions = {0.1f, 0.2f, 0.3f, -1.0f / 3.0f, 2.0f, 1e-30f};
    snapshot.velocities = {3.0f, -0.7f, 0.0f, 1.5f, 2.25f, -9.81f};
    snapshot.radii = {0.1f, 0.2f};
    io::TraceWriter trace;
    const QString path = m_dir.filePath(u"snapshot.csv"_s);
    QCOMPARE(trace.open(path), QString());
    trace.writeRows(snapshot);
    trace.writeRows(snapshot);
    QCOMPARE(trace.close(), QString());

    // the same header, a row per particle per call, every float as itself
    QByteArray header;
    const auto rows = readTraceRows(path, &header);
    QCOMPARE(header, QByteArray(io::kTraceHeader));
    QCOMPARE(rows.size(), 4);
    QCOMPARE(rows[0][3], QByteArray("0.1"));  // the float's own shortest text, not its double's
    for (int row = 0; row < 4; ++row) {
        const int i = row % 2;
        QCOMPARE(rows[row].size(), 9);
        QCOMPARE(rows[row][0], QByteArray("12"));
        QCOMPARE(parseNumber<double>(rows[row][1]), 0.06);
        QCOMPARE(rows[row][2].toInt(), i);
        for (int axis = 0; axis < 3; ++axis) {
            QCOMPARE(parseNumber<float>(rows[row][3 + axis]), snapshot.positions[std::size_t(3 * i + axis)]);
            QCOMPARE(parseNumber<float>(rows[row][6 + axis]), snapshot.velocities[std::size_t(3 * i + axis)]);
        }
    }
}

void TestTraceWriter::snapshotWithoutVelocitiesWritesZeros()
{
    core::Snapshot snapshot;
    snapshot.positions = {1.0f, 2.0f, 3.0f};
    io::TraceWriter trace;
    const QString path = m_dir.filePath(u"still.csv"_s);
    QCOMPARE(trace.open(path), QString());
    trace.writeRows(snapshot);
    QCOMPARE(trace.close(), QString());
    QByteArray header;
    const auto rows = readTraceRows(path, &header);
    QCOMPARE(rows.size(), 1);
    QCOMPARE(rows[0].mid(3), (QList<QByteArray>{"1", "2", "3", "0", "0", "0"}));
}

void TestTraceWriter::unwritableFileIsNamed()
{
    io::TraceWriter trace;
    const QString error = trace.open(m_dir.filePath(u"no/such/folder/trace.csv"_s));
    QVERIFY2(error.contains(u"trace.csv: cannot write the trace"_s), qPrintable(error));
}

QTEST_GUILESS_MAIN(TestTraceWriter)
#include "test_trace_writer.moc"
