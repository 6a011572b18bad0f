# Copies the part of MathJax 2 the manual uses (TeX input, HTML-CSS output
# with the TeX web fonts) from SOURCE (Debian's libjs-mathjax) to DESTINATION,
# following the package's symbolic links to its fonts:
#   cmake -DSOURCE=/usr/share/javascript/mathjax -DDESTINATION=html/mathjax -P copy_mathjax.cmake
# About 5 MB. Without SOURCE/MathJax.js nothing is copied (the formulas then
# show as LaTeX source; CMake warned at configure time).
if(NOT EXISTS ${SOURCE}/MathJax.js)
  return()
endif()
file(REMOVE_RECURSE ${DESTINATION})
set(parts MathJax.js extensions jax/input/TeX jax/output/HTML-CSS jax/element fonts/HTML-CSS/TeX/woff)
foreach(part IN LISTS parts)
  get_filename_component(parent ${DESTINATION}/${part} DIRECTORY)
  file(MAKE_DIRECTORY ${parent})
  execute_process(COMMAND cp -rL ${SOURCE}/${part} ${parent}/ RESULT_VARIABLE failed)
  if(failed)
    message(FATAL_ERROR "could not copy ${SOURCE}/${part}")
  endif()
endforeach()
