# Writes OUT, a header defining NSM_VERSION: "git COMMIT" (with "-modified" when
# the work tree differs from it), or, built outside a git work tree (from a
# tarball), the VERSION file's text, or "unknown". Run at every build; OUT is
# rewritten only when the version changes, so nothing recompiles otherwise.
execute_process(COMMAND git -C "${SOURCE}" describe --always --dirty=-modified --abbrev=12
                OUTPUT_VARIABLE version RESULT_VARIABLE status OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(status EQUAL 0 AND NOT version STREQUAL "")
  set(version "git ${version}")
elseif(EXISTS "${SOURCE}/VERSION")
  file(STRINGS "${SOURCE}/VERSION" version LIMIT_COUNT 1)
else()
  set(version "unknown (built outside a git work tree, without a VERSION file)")
endif()
file(WRITE "${OUT}.new" "#define NSM_VERSION \"${version}\"\n")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different "${OUT}.new" "${OUT}")
