# Writes ${OUTPUT}: the page's files as C++ string constants (locus::view::assets), so that the
# binary serves them without reading files at run time (the page cannot be pointed elsewhere).
# Invoked at build time: cmake -DSOURCE_DIR=... -DOUTPUT=... -P embed_assets.cmake
set(content "// Generated from view/assets/ by view/embed_assets.cmake; do not edit.\n")
string(APPEND content "#include \"view/assets.h\"\n\nnamespace locus::view::assets {\n")
foreach(pair "index_html:index.html" "app_js:app.js" "style_css:style.css")
    string(REPLACE ":" ";" parts "${pair}")
    list(GET parts 0 name)
    list(GET parts 1 file)
    file(READ "${SOURCE_DIR}/assets/${file}" text)
    string(FIND "${text}" ")locus_asset\"" clash)
    if(NOT clash EQUAL -1)
        message(FATAL_ERROR "${file} contains the raw-string delimiter")
    endif()
    string(APPEND content "const std::string_view ${name} = R\"locus_asset(${text})locus_asset\";\n")
endforeach()
string(APPEND content "}  // namespace locus::view::assets\n")
file(WRITE "${OUTPUT}.tmp" "${content}")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
