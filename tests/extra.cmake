# Per-test link needs beyond an area's default (included by tests/CMakeLists.txt).
# hfxc's --annotations / --reflect output is read back with cJSON, as the hfxc program writes it.
if(TARGET tools_test_hfxc AND TARGET hfx_cjson)
  target_link_libraries(tools_test_hfxc PRIVATE hfx_cjson)
  target_compile_definitions(tools_test_hfxc PRIVATE HFX_HAVE_CJSON=1)
endif()
if(TARGET tools_test_hfxc AND TARGET hfxc)
  add_dependencies(tools_test_hfxc hfxc) # the test runs the built program
endif()
