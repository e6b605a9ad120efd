# The Debian package (make package): CPack's DEB generator over the install rules of
# packaging/. The libraries it needs are computed from the binaries (dpkg-shlibdeps); Qt's
# platform plugins, which no binary links, are named.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME prisca-lab)
set(CPACK_PACKAGE_VENDOR "The PRISCA Lab developers")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "teach a robot to repeat one demonstrated manoeuvre")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_PACKAGE_RELEASE 1)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # prisca-lab_<version>-1_<arch>.deb
# The project has no mail domain yet: the reserved .invalid says so rather than invent one.
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "The PRISCA Lab developers <developers@prisca-lab.invalid>")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libqt6svg6, qt6-translations-l10n, fonts-noto-cjk, bash-completion")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "avrdude")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
# The synopsis is CPACK_PACKAGE_DESCRIPTION_SUMMARY; CPack indents these lines by one space.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "PRISCA Lab implements PRISCA, an online policy-search method that needs a
single demonstration and a coarse sign model of the dynamics. A lab operator
records a demonstration from a ceiling infrared camera, fits the action
mapping, identifies the car and runs PRISCA and its baselines on an RC car
over a serial transmitter link or on simulated plants, with live plots.
.
This package holds the window (prisca), the headless commands (prisca-cli),
the bridge firmware for transmitter trainer ports and a udev rule that lets
the operator open common USB-serial adapters.")
include(CPack)
