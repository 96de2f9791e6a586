# The Debian package: `cpack -G DEB` in the build folder writes sdfwb_<version>_<arch>.deb holding
# what `cmake --install` installs under /usr: bin/sdfwb, share/sdfwb/ (the dataset, shaders/lib,
# matcaps: the binary finds them through its own prefix, core/src/Paths.cpp), the Python package in
# lib/python3/dist-packages/sdfwb (Debian's /usr/bin/python3), the desktop entry, its icons and the
# MIME type of .glsl files, bash completion and the man page, which help2man makes from the built
# binary's --help at build time. Depends: dpkg-shlibdeps' libraries plus what is loaded at run time
# (EGL and Mesa through libepoxy, the Qt platform plugins, the interpreter and NumPy).
# tests/package/check_deb.sh (ctest package.InstallsAndRuns) builds, installs and removes it.
#
# Run with -P (the man page step below), this file makes the man page instead:
#   cmake -DBINARY=... -DINCLUDE=... -DOUTPUT=... -DHELP2MAN=... -P Packaging.cmake

if(CMAKE_SCRIPT_MODE_FILE)
  # help2man renders `sdfwb --help` and `--version`; the per-command options (`sdfwb --batch
  # COMMAND --help`, the commands read from --help's "batch commands:" list) go in as a section of
  # their own, after the hand-written ENVIRONMENT and FILES of INCLUDE.
  set(ENV{ASAN_OPTIONS} "detect_leaks=0")
  execute_process(COMMAND ${BINARY} --help OUTPUT_VARIABLE help RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${BINARY} --help exited with ${status}")
  endif()
  string(REGEX MATCH "\nbatch commands:\n(.*)" commands_block "${help}")
  string(REGEX MATCHALL "\n  ([a-z]+)  " command_lines "\n${CMAKE_MATCH_1}\n")
  file(READ ${INCLUDE} text)
  string(APPEND text "\n[COMMAND OPTIONS]\n")
  set(count 0)
  foreach(line IN LISTS command_lines)
    string(STRIP "${line}" command)
    execute_process(COMMAND ${BINARY} --batch ${command} --help OUTPUT_VARIABLE options RESULT_VARIABLE status)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "${BINARY} --batch ${command} --help exited with ${status}")
    endif()
    # roff: a backslash is \e, and a line may not start with . or '
    string(REPLACE "\\" "\\e" options "${options}")
    string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" options "${options}")
    string(APPEND text ".SS \"sdfwb \\-\\-batch ${command}\"\n.nf\n${options}.fi\n")
    math(EXPR count "${count} + 1")
  endforeach()
  if(count LESS 5)
    message(FATAL_ERROR "found ${count} batch commands in `${BINARY} --help`: its \"batch commands:\" list changed shape")
  endif()
  get_filename_component(output_dir ${OUTPUT} DIRECTORY)
  file(WRITE ${output_dir}/sdfwb.h2m "${text}")
  execute_process(
    COMMAND ${HELP2MAN} --no-info --section=1 --name=${NAME} --include=${output_dir}/sdfwb.h2m
            --output=${output_dir}/sdfwb.1 ${BINARY}
    RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "help2man failed (${status})")
  endif()
  # Debian compresses man pages (gzip -9n: no name or time stamp, so the bytes repeat).
  execute_process(COMMAND gzip -9nf ${output_dir}/sdfwb.1 RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "gzip failed (${status})")
  endif()
  return()
endif()

set(SDFWB_RESOURCES ${PROJECT_SOURCE_DIR}/resources)

# --- the man page -------------------------------------------------------------------------------
find_program(SDFWB_HELP2MAN help2man)
if(NOT SDFWB_HELP2MAN)
  message(FATAL_ERROR "sdfwb: the man page needs help2man: not found. scripts/bootstrap installs it.")
endif()
set(SDFWB_MAN_PAGE ${CMAKE_BINARY_DIR}/packaging/sdfwb.1.gz)
add_custom_command(
  OUTPUT ${SDFWB_MAN_PAGE}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/packaging
  COMMAND ${CMAKE_COMMAND} -DBINARY=$<TARGET_FILE:sdfwb> -DINCLUDE=${SDFWB_RESOURCES}/man/sdfwb.h2m
          -DOUTPUT=${SDFWB_MAN_PAGE} -DHELP2MAN=${SDFWB_HELP2MAN} "-DNAME=the SDF Workbench"
          -P ${CMAKE_CURRENT_LIST_FILE}
  DEPENDS sdfwb ${SDFWB_RESOURCES}/man/sdfwb.h2m ${CMAKE_CURRENT_LIST_FILE}
  COMMENT "Generating the man page (help2man)"
  VERBATIM)
add_custom_target(sdfwb_man_page ALL DEPENDS ${SDFWB_MAN_PAGE})
install(FILES ${SDFWB_MAN_PAGE} DESTINATION share/man/man1)

# --- shell and desktop integration --------------------------------------------------------------
install(FILES ${SDFWB_RESOURCES}/bash-completion/sdfwb DESTINATION share/bash-completion/completions)
if(SDFWB_BUILD_GUI)
  install(FILES ${SDFWB_RESOURCES}/desktop/sdfwb.desktop DESTINATION share/applications)
  # Debian 12's shared-mime-info has no type for .glsl: text/x-glsl is declared here.
  install(FILES ${SDFWB_RESOURCES}/desktop/sdfwb.xml DESTINATION share/mime/packages)
  install(FILES ${SDFWB_RESOURCES}/icons/sdfwb.svg DESTINATION share/icons/hicolor/scalable/apps)
  install(FILES ${SDFWB_RESOURCES}/icons/sdfwb.png DESTINATION share/icons/hicolor/256x256/apps)
endif()

# --- CPack --------------------------------------------------------------------------------------
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME sdfwb)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "sdfwb authors")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "SDF Workbench: author, debug, render and sample signed distance functions")
set(CPACK_PACKAGE_DESCRIPTION
    "A desktop workbench and a headless command line for GLSL signed distance functions: an editor\n"
    "with live diagnostics, a sphere-traced viewport, a cutting plane, a march debugger, renders,\n"
    "videos, meshes and sample sets for machine learning, with a dataset of SDFs. The command line\n"
    "(sdfwb --batch) and the Python module (import sdfwb) render through EGL and need no display.")
string(JOIN "" CPACK_PACKAGE_DESCRIPTION ${CPACK_PACKAGE_DESCRIPTION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
# The build is RelWithDebInfo: the package holds the binaries without their debug sections.
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "sdfwb authors" CACHE STRING "The .deb's Maintainer field")
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
# Loaded at run time, so dpkg-shlibdeps cannot see them: libepoxy opens libEGL, which needs a
# vendor (Mesa's, with llvmpipe in libgl1-mesa-dri when there is no GPU).
set(SDFWB_DEB_DEPENDS libegl1 libgl1-mesa-dri)
if(SDFWB_BUILD_GUI)
  list(APPEND SDFWB_DEB_DEPENDS qt6-qpa-plugins)
endif()
if(SDFWB_BUILD_PYTHON)
  # The native module is built for one interpreter version (its ABI tag is in the file name).
  math(EXPR SDFWB_PYTHON_NEXT_MINOR "${Python_VERSION_MINOR} + 1")
  list(APPEND SDFWB_DEB_DEPENDS "python3 (>= ${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}~)"
       "python3 (<< ${Python_VERSION_MAJOR}.${SDFWB_PYTHON_NEXT_MINOR})" python3-numpy)
  # Debian's own pattern for Python files: byte-compile after unpacking, remove the caches before
  # removal (py3compile and py3clean come with python3).
  set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${SDFWB_RESOURCES}/debian/postinst ${SDFWB_RESOURCES}/debian/prerm)
endif()
list(JOIN SDFWB_DEB_DEPENDS ", " CPACK_DEBIAN_PACKAGE_DEPENDS)
# The render overlay's font; the editor's Chinese and Japanese glyphs (comments in pasted shaders).
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "fonts-dejavu-core, fonts-wqy-microhei")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "python3-matplotlib, python3-torch")
include(CPack)
