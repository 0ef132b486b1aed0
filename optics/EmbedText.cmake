# Writes OUTPUT, a C++ source defining `const char SYMBOL[]` (declared in HEADER) with the text of
# INPUT, so that the library carries its data and reads no file at run time. Run at build time:
#   cmake -DINPUT=... -DOUTPUT=... -DHEADER=... -DSYMBOL=... -P EmbedText.cmake
file(READ "${INPUT}" text)
string(FIND "${text}" ")embedded\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "${INPUT} contains the raw string's closing delimiter")
endif()
file(WRITE "${OUTPUT}.tmp" "// Generated from ${INPUT} by EmbedText.cmake; do not edit.\n"
  "#include \"${HEADER}\"\n\nnamespace lenslab {\nconst char ${SYMBOL}[] = R\"embedded(${text})embedded\";\n}\n")
file(RENAME "${OUTPUT}.tmp" "${OUTPUT}")
