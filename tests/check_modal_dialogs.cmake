cmake_minimum_required(VERSION 3.24)
# Fails when the window's code opens a dialog Qt's own way (QDialog::exec(), QFileDialog::get...,
# QMessageBox::warning/question/..., QInputDialog::get...): such a dialog is application-modal and
# blocks the E-STOP button. Every dialog goes through app/widgets/ModalDialog, which never blocks
# E-STOP. Every folder of the window is checked (prisca-cli, under app/cli/, opens no window).
# Run by CTest as: cmake -DSOURCE_DIR=... -P check_modal_dialogs.cmake
file(GLOB_RECURSE sources "${SOURCE_DIR}/app/*.cpp" "${SOURCE_DIR}/app/*.h")
list(FILTER sources EXCLUDE REGEX "/app/cli/")
set(pattern "(QFileDialog::get|QMessageBox::(warning|question|information|critical|about)[ \t]*\\(|QInputDialog::get|QColorDialog::get|QFontDialog::get|[.>]exec\\(\\))")
set(checked 0)
foreach(src IN LISTS sources)
    if(src MATCHES "/ModalDialog\\.(cpp|h)$")
        continue()
    endif()
    math(EXPR checked "${checked} + 1")
    file(STRINGS "${src}" lines REGEX "${pattern}")
    foreach(line IN LISTS lines)
        if(NOT line MATCHES "^[ \t]*//")
            message(FATAL_ERROR "${src}: '${line}': open dialogs through ModalDialog, which never blocks E-STOP")
        endif()
    endforeach()
endforeach()
message(STATUS "${checked} sources of the window open their dialogs through ModalDialog")
