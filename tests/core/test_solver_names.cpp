// The contact solvers' names: each solver has one, the name reads back as that solver, and any
// other text (another case, a blank) is no solver, so a file or a command line naming it is refused.

#include "core/contacts/solver_names.h"

#include <QTest>

#include <string>

Q_DECLARE_METATYPE(std::string)

class TestSolverNames : public QObject {
    Q_OBJECT

private slots:
    void everySolverHasAName();
    void otherNamesAreNoSolver_data();
    void otherNamesAreNoSolver();
};

void TestSolverNames::everySolverHasAName()
{
    QCOMPARE(std::size(core::kContactSolvers), std::size_t(2));
    QVERIFY(core::kContactSolvers[0] == core::ContactSolver::Iterative);  // the default comes first
    QCOMPARE(core::contactSolverName(core::ContactSolver::Iterative), std::string_view("iterative"));
    QCOMPARE(core::contactSolverName(core::ContactSolver::Handout), std::string_view("handout"));
    for (core::ContactSolver solver : core::kContactSolvers)
        QVERIFY(core::contactSolverFromName(core::contactSolverName(solver)) == solver);
}

void TestSolverNames::otherNamesAreNoSolver_data()
{
    QTest::addColumn<std::string>("name");
    QTest::newRow("capitals") << std::string("Iterative");
    QTest::newRow("blank") << std::string();
    QTest::newRow("padded") << std::string(" handout");
    QTest::newRow("unknown") << std::string("unknown");
    QTest::newRow("another engine's") << std::string("pgs");
}

void TestSolverNames::otherNamesAreNoSolver()
{
    QFETCH(std::string, name);
    QVERIFY(!core::contactSolverFromName(name));
}

QTEST_APPLESS_MAIN(TestSolverNames)
#include "test_solver_names.moc"
