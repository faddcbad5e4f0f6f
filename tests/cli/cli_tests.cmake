# Tests of the eg2d command (tools/eg2d), driven by cli_test.py under the system
# Python (/usr/bin/python3: its xml module checks the pictures).
set(EG2D_CLI_PYTHON /usr/bin/python3)
set(EG2D_CLI_TEST ${CMAKE_CURRENT_LIST_DIR}/cli_test.py)
set(EG2D_CLI_ARGS $<TARGET_FILE:eg2d_tool> ${PROJECT_SOURCE_DIR}/examples)

# Every example case runs, at a small size, converged and unfolded, and its files are written.
file(GLOB EG2D_CLI_EXAMPLES CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/examples/*.toml)
foreach(path IN LISTS EG2D_CLI_EXAMPLES)
  get_filename_component(name ${path} NAME_WE)
  set(size 33x33)
  if(name MATCHES "annulus|rose")
    set(size 65x25)   # O-grids need points around the body
  elseif(name MATCHES "naca")
    set(size 97x33)   # and the airfoils' wall control more (at 65x25 point SOR stalls on the O-grid)
  elseif(name MATCHES "flat-plate|bump-in-channel")
    set(size 137x97)  # wall-resolved: fewer rows cannot grow by at most 1.2 from their first cells
    if(name MATCHES "bump")
      set(size 177x81)
    endif()
  elseif(name MATCHES "bend|pipe-with-body")
    set(size 257x129)
  elseif(name MATCHES "s-diffuser")
    set(size 257x161)
  endif()
  file(STRINGS ${path} block_tables REGEX "^\\[\\[blocks\\]\\]")
  if(block_tables)
    set(size blocks)  # a set of blocks: each block at its own size (no --size)
  endif()
  add_test(NAME cli_example_${name} COMMAND ${EG2D_CLI_PYTHON} ${EG2D_CLI_TEST} ${EG2D_CLI_ARGS} --example ${name} ${size})
  # the command traps invalid, divide-by-zero and overflow, as a host may (main.cpp)
  set_tests_properties(cli_example_${name} PROPERTIES ENVIRONMENT EG2D_FP_TRAPS=1)
endforeach()

foreach(group ErrorMessages CaseParameters Sides Controls CommandLine Demo Progress Patches RunFiles Airfoil AirfoilOutputSet Channel SharpTrailingEdge
              InteriorLines BlockSets)
  add_test(NAME cli_${group} COMMAND ${EG2D_CLI_PYTHON} ${EG2D_CLI_TEST} ${EG2D_CLI_ARGS} ${group})
  set_tests_properties(cli_${group} PROPERTIES ENVIRONMENT EG2D_FP_TRAPS=1)
endforeach()

# docs/tables.md is what the library's tables say now (eg2d --tables).
add_test(NAME docs_tables_up_to_date
         COMMAND ${EG2D_CLI_PYTHON} ${PROJECT_SOURCE_DIR}/tools/eg2d/tables_doc.py $<TARGET_FILE:eg2d_tool> ${PROJECT_SOURCE_DIR} --check)

# Every gallery picture is what the tool makes now of the case file beside it.
add_test(NAME gallery_up_to_date
         COMMAND ${EG2D_CLI_PYTHON} ${PROJECT_SOURCE_DIR}/tools/eg2d/gallery.py $<TARGET_FILE:eg2d_tool> ${PROJECT_SOURCE_DIR} --check)

# Issue 39's bounds against blockMesh on its own blocks (pitzDaily, TMR's
# step) with the walls' first cells: bench/blockmesh/compare.py --check.
find_program(EG2D_BLOCKMESH blockMesh)
if(EG2D_BLOCKMESH)
  add_test(NAME cli_blockmesh_walls
           COMMAND ${EG2D_CLI_PYTHON} ${PROJECT_SOURCE_DIR}/bench/blockmesh/compare.py $<TARGET_FILE:eg2d_tool> --walls --check)
  set_tests_properties(cli_blockmesh_walls PROPERTIES LABELS "script" ENVIRONMENT EG2D_FP_TRAPS=1)
endif()
