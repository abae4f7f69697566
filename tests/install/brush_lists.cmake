# Shared by install_test and deb_test: the built-in brushes (the plugins/brushes folders) and the
# brushes an installed octaclay-cli lists, each checked to come from the installed data.

# The built-in brush ids, sorted: one per folder of <source>/plugins/brushes.
function(built_in_brushes source_dir ids_var)
  file(GLOB folders LIST_DIRECTORIES true RELATIVE "${source_dir}/plugins/brushes"
       "${source_dir}/plugins/brushes/*")
  set(ids)
  foreach(f IN LISTS folders)
    if(IS_DIRECTORY "${source_dir}/plugins/brushes/${f}")
      list(APPEND ids ${f})
    endif()
  endforeach()
  list(SORT ids)
  set(${ids_var} "${ids}" PARENT_SCOPE)
endfunction()

# The ids in `octaclay-cli brushes --json` output, sorted; fails unless every brush's folder lies
# under brushes_folder.
function(listed_brushes json brushes_folder ids_var)
  string(JSON count LENGTH "${json}" brushes)
  set(ids)
  if(count GREATER 0)
    math(EXPR last "${count} - 1")
    foreach(k RANGE ${last})
      string(JSON id GET "${json}" brushes ${k} id)
      string(JSON folder GET "${json}" brushes ${k} folder)
      string(FIND "${folder}" "${brushes_folder}/" at)
      if(NOT at EQUAL 0)
        message(FATAL_ERROR "brush ${id} was read from ${folder}, not ${brushes_folder}")
      endif()
      list(APPEND ids ${id})
    endforeach()
  endif()
  list(SORT ids)
  set(${ids_var} "${ids}" PARENT_SCOPE)
endfunction()
