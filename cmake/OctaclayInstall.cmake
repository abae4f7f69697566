# Installs Octaclay as a desktop application (GNUInstallDirs): octaclay and octaclay-cli in bin/
# (app/CMakeLists.txt), the built-in brushes and resources in share/octaclay/, where the
# installed binaries look (app/session/data_folders.h), the .desktop file and the icon; and the
# Debian package through CPack (scripts/package).
include(GNUInstallDirs)

set(OCTACLAY_DATA_DESTINATION ${CMAKE_INSTALL_DATADIR}/octaclay)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/plugins/brushes/
        DESTINATION ${OCTACLAY_DATA_DESTINATION}/brushes)
# materials/, environment/, icons/ …: share/octaclay holds what resources/ holds.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/resources/ DESTINATION ${OCTACLAY_DATA_DESTINATION}
        PATTERN .gitkeep EXCLUDE)
install(FILES ${PROJECT_SOURCE_DIR}/packaging/octaclay.desktop
        DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${PROJECT_SOURCE_DIR}/packaging/octaclay.svg
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
install(FILES ${PROJECT_SOURCE_DIR}/packaging/README.md
        DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/octaclay RENAME packaging.md)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME octaclay)
set(CPACK_PACKAGE_VENDOR "Octaclay")
set(CPACK_PACKAGE_CONTACT "Octaclay developers <octaclay@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Sculpt and paint clay-like 3D models stored as octahedral geometry images")
set(CPACK_PACKAGE_DESCRIPTION
    "A desktop modeller for people who have never modelled: push, pull, smooth and paint one \
closed surface with brushes, export it as OBJ, glTF, PLY, STL or OFF. Includes octaclay-cli.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
# The libraries the binaries link, as Debian 12 names them (dpkg-shlibdeps); Qt's platform
# plugins and Mesa's GL drivers are loaded at run time, so they are named here.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins, libqt6svg6, libgl1-mesa-dri, libegl-mesa0")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "hicolor-icon-theme")
include(CPack)
