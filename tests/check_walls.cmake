# Dependency walls (docs/design.md): run by CTest as `cmake -DROOT=<repo> -P check_walls.cmake`.
#   core/   standard library and core/ only
#   float/  no GMP, no CGAL, nothing from exact/ or proofs/
#   proofs/ no CGAL, nothing from exact/, core/, float/, cli/
#   exact/, cli/: no peer library (qhull, cddlib, GLPK) and nothing from bench/
set(failures "")
function(check_dir dir forbidden_regex what)
  file(GLOB_RECURSE files "${ROOT}/${dir}/*.h" "${ROOT}/${dir}/*.hpp" "${ROOT}/${dir}/*.cpp")
  foreach(f IN LISTS files)
    file(STRINGS "${f}" lines REGEX "^[ \t]*#[ \t]*include")
    foreach(line IN LISTS lines)
      if(line MATCHES "${forbidden_regex}")
        set(failures "${failures}\n  ${f}: ${line}  (${what})" PARENT_SCOPE)
      endif()
    endforeach()
  endforeach()
endfunction()
check_dir(core "<gmp|<CGAL/|<boost/|\"(exact|float|proofs|cli)/" "core/ is standard library only")
check_dir(float "<gmp|<CGAL/|\"(exact|proofs|cli)/" "float/ has no GMP, no CGAL, no exact engine")
check_dir(proofs "<CGAL/|\"(exact|core|float|cli)/" "proofs/ shares no code with the engine")
# The benchmarks' peers (qhull, cddlib, GLPK, bench/) are never part of the engine or the command.
foreach(dir exact cli)
  check_dir(${dir} "<libqhull|<cdd/|<glpk|\"bench/" "peers stay in bench/")
endforeach()
if(failures)
  message(FATAL_ERROR "dependency walls broken:${failures}")
endif()
message(STATUS "dependency walls hold")
