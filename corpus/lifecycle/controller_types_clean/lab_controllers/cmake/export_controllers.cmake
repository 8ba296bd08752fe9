# the controllers' descriptions are generated into the build folder
pluginlib_export_plugin_description_file(controller_interface ${CMAKE_BINARY_DIR}/generated.xml)
