# Precompiled headers. Qt's headers, and QCustomPlot's (which pulls in most of QtWidgets and
# QtPrintSupport), are parsed again by every file that includes them: a window file that draws a
# plot took 15-22 s to compile, most of it in qcustomplot.h. Each library precompiles the headers
# its files share once; the test executables, one per test, reuse one precompiled header per kind
# (core or window) instead of making their own, which would cost more than it saves.
option(MBSCOPE_PCH "Precompile the Qt and QCustomPlot headers most files include" ON)
add_feature_info(PCH MBSCOPE_PCH "precompiled Qt headers")

set(MBSCOPE_PCH_CORE
    <QtCore/QByteArray> <QtCore/QByteArrayView> <QtCore/QDateTime> <QtCore/QHash> <QtCore/QJsonArray>
    <QtCore/QJsonDocument> <QtCore/QJsonObject> <QtCore/QList> <QtCore/QMap> <QtCore/QObject>
    <QtCore/QString> <QtCore/QStringList> <QtCore/QTimer> <QtCore/QVariant> <QtNetwork/QAbstractSocket>
    <algorithm> <functional> <memory> <optional> <vector>)
set(MBSCOPE_PCH_UI ${MBSCOPE_PCH_CORE} <QtWidgets/QtWidgets> <qcustomplot.h>)

function(mbscope_use_pch target kind)
    if(MBSCOPE_PCH)
        target_precompile_headers(${target} PRIVATE ${MBSCOPE_PCH_${kind}})
    endif()
endfunction()

# An object library that only makes the precompiled header a kind of test reuses: it links what
# those tests link, so that its compile flags are theirs.
function(mbscope_add_test_pch name kind)
    if(NOT MBSCOPE_PCH)
        return()
    endif()
    set(source "${CMAKE_CURRENT_BINARY_DIR}/${name}.cpp")
    file(WRITE "${source}.in" "// The translation unit that makes ${name}'s precompiled header.\n")
    configure_file("${source}.in" "${source}" COPYONLY)
    add_library(${name} OBJECT "${source}")
    target_link_libraries(${name} PRIVATE Qt6::Test ${ARGN})
    target_compile_definitions(${name} PRIVATE MBSCOPE_TEST_DATA_DIR="${MBSCOPE_TEST_DATA_DIR}")
    mbscope_set_warnings(${name})
    target_precompile_headers(${name} PRIVATE ${MBSCOPE_PCH_${kind}} <QtTest/QtTest>)
endfunction()
