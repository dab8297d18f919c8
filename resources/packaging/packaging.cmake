# The Debian package: `cpack -G DEB` in a configured build folder (the README says how). It
# holds exactly what `cmake --install` installs, under /usr; its dependencies are what
# dpkg-shlibdeps finds the executable linked against. No maintainer scripts: the desktop, MIME
# and icon caches are refreshed by the triggers of desktop-file-utils, shared-mime-info and
# hicolor-icon-theme.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME finbook)
set(CPACK_PACKAGE_VENDOR "The Finbook developers")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "flipbook animation editor with deformable drawings")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_PACKAGE_CHECKSUM SHA256)

set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # finbook_VERSION_ARCH.deb
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "The Finbook developers <finbook@users.noreply.github.com>")
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://github.com/finbook/finbook")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Not linked, so dpkg-shlibdeps cannot see it: the SVG icon engine plugin that draws every
# toolbar and tool icon (all SVG) comes with libqt6svg6.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libqt6svg6 (>= 6.4)")
# The X11 platform plugin ships with libqt6gui6; these add Wayland, Qt's own translations and
# the encoder that GIF/MP4/WebM/APNG export runs, and the US English models lip sync recognises
# speech with (without them it follows the loudness).
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS
    "ffmpeg, pocketsphinx-en-us, qt6-qpa-plugins, qt6-translations-l10n, qt6-wayland")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
# CPack puts the summary on the first line and this text below it.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "Finbook is a desktop flipbook animation editor. Draw a character once, then
deform the drawing to make the next frame - with as-rigid-as-possible pins,
harmonic cages or automatic skeletons - and keep editing the result as
ordinary strokes. It generates in-betweens between two keys and exports to
PNG, SVG, GIF, MP4, WebM, APNG and HTML.")

include(CPack)
