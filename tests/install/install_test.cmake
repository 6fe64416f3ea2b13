# `cmake --install` into a scratch prefix, then the installed tools run from there with nothing of the
# source or build tree: every tool prints the project's version, the installed ochre renders a copy of
# the installed Cornell box in a scratch directory, and the installed Python package renders it too.
#   cmake -DBUILD_DIR=<build> -DPREFIX=<scratch prefix> -DWORK_DIR=<scratch dir> -DVERSION=<x.y.z>
#         -DSOURCE_DIR=<source> [-DPYTHON=<python3> -DPYTHON_DIR=<package dir in the prefix>]
#         -P install_test.cmake

function(fail)
  string(JOIN "" message ${ARGN})
  message(FATAL_ERROR "${message}")
endfunction()

# Runs a command, fails with its output unless it exits 0; OUT receives its stdout.
function(run out)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE stdout ERROR_VARIABLE stderr
                  WORKING_DIRECTORY ${WORK_DIR})
  if(NOT code EQUAL 0)
    fail("`${ARGN}` exited with ${code}:\n${stdout}${stderr}")
  endif()
  set(${out} "${stdout}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${PREFIX} ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
run(ignored ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PREFIX})

set(tools ochre ochre-diff ochre-regress ochre-converge ochre-bench ochre-brdf ochre-halfspace ochre-vgroove
          ochre-fit ochre-slurm)
set(expected_files
    share/ochre/scripts/plot_brdf.py share/ochre/scripts/plot_convergence.py share/ochre/scripts/plot_fit.py
    share/ochre/scripts/one_node_cluster.sh
    share/ochre/scenes/default/default.json share/ochre/scenes/cornell-box/cornell-box.json
    share/doc/ochre/LICENSE share/doc/ochre/README.md share/doc/ochre/cli.md share/doc/ochre/scene-format.md)
foreach(tool IN LISTS tools)
  list(APPEND expected_files bin/${tool})
endforeach()
foreach(file IN LISTS expected_files)
  if(NOT EXISTS ${PREFIX}/${file})
    fail("not installed: ${PREFIX}/${file}")
  endif()
endforeach()

foreach(tool IN LISTS tools)
  run(printed ${PREFIX}/bin/${tool} --version)
  if(NOT printed STREQUAL "${tool} ${VERSION}\n")
    fail("${tool} --version printed '${printed}', expected '${tool} ${VERSION}' (project(VERSION) of CMakeLists.txt)")
  endif()
endforeach()

# The installed ochre names no directory of the source tree, so it cannot depend on it at run time.
file(STRINGS ${PREFIX}/bin/ochre source_paths REGEX "${SOURCE_DIR}/")
if(source_paths)
  fail("the installed ochre refers to the source tree: ${source_paths}")
endif()

# A scene with its assets (meshes, spectra), copied away from both trees, rendered by the installed ochre.
file(COPY ${PREFIX}/share/ochre/scenes/cornell-box DESTINATION ${WORK_DIR})
unset(ENV{OCIO})
run(ignored ${PREFIX}/bin/ochre render ${WORK_DIR}/cornell-box/cornell-box.json -o ${WORK_DIR}/out.exr
    --png ${WORK_DIR}/out.png --resolution 16x16 --spp 2 -q)
foreach(file out.exr out.png)
  if(NOT EXISTS ${WORK_DIR}/${file})
    fail("the installed ochre did not write ${WORK_DIR}/${file}")
  endif()
endforeach()
# The installed ochre-regress writes a complete HTML report: its stylesheet and script are compiled in.
file(COPY ${SOURCE_DIR}/tests/regression/spot_light.json DESTINATION ${WORK_DIR}/suite)
file(COPY ${SOURCE_DIR}/tests/regression/references/spot_light.exr DESTINATION ${WORK_DIR}/suite/references)
run(ignored ${PREFIX}/bin/ochre-regress ${WORK_DIR}/suite --html ${WORK_DIR}/report)
foreach(asset report.css report.js)
  file(READ ${WORK_DIR}/report/${asset} written)
  file(READ ${SOURCE_DIR}/tools/regress/report/${asset} source)
  if(NOT written STREQUAL source)
    fail("the installed ochre-regress wrote ${WORK_DIR}/report/${asset} unlike tools/regress/report/${asset}")
  endif()
endforeach()
# The Python package: imported from the prefix alone (PYTHONPATH=PREFIX/PYTHON_DIR), it reports the version,
# renders the copied scene to the bits the installed ochre wrote and loads a textured scene (the image
# library module of PREFIX/lib/ochre, renderer/image/image_library.h).
if(PYTHON)
  set(ENV{PYTHONPATH} ${PREFIX}/${PYTHON_DIR})
  run(printed ${PYTHON} -c "
import ochre, numpy
assert ochre.__file__.startswith('${PREFIX}/'), ochre.__file__
r = ochre.load_scene('${WORK_DIR}/cornell-box/cornell-box.json', resolution=(16, 16), spp=2).render()
cli, _ = ochre.read_exr('${WORK_DIR}/out.exr')
assert numpy.array_equal(r.rgb[..., 0], cli['R']), 'Python and the installed ochre differ'
# A scene with a texture and an HDR map: the package finds the image library module of the prefix.
ochre.load_scene('${PREFIX}/share/ochre/scenes/benchmark/rock-gold.json', resolution=(8, 8), spp=1)
print(ochre.__version__)")
  if(NOT printed STREQUAL "${VERSION}\n")
    fail("the installed Python module printed '${printed}', expected '${VERSION}'")
  endif()
  unset(ENV{PYTHONPATH})
endif()
message(STATUS "installed into ${PREFIX}; every tool prints ${VERSION}; the installed ochre rendered ${WORK_DIR}/out.exr; "
               "the installed ochre-regress wrote ${WORK_DIR}/report")
