#pragma once
// What the editor's UI tests set up alike: OpenGL before the application exists, and the
// application's settings (autosave, recent files, docks) in a throwaway folder, never the user's.

#include "ui/viewport/viewport.h"

#include <QCoreApplication>
#include <QSettings>
#include <QSurfaceFormat>

namespace test {

// for a test class's static initMain(): the viewport is a QOpenGLWidget, whose format and shared
// contexts must be set before the QApplication exists
inline void prepareOpenGL()
{
    QSurfaceFormat::setDefaultFormat(ui::Viewport::requestedFormat());
    QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);
}

// the settings as an ini file in folder, under the test's own name
inline void useSettingsIn(const QString &folder, const QString &testName)
{
    QCoreApplication::setOrganizationName(QStringLiteral("SpringlabTests"));
    QCoreApplication::setApplicationName(testName);
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, folder);
}

}  // namespace test
