# Writes INPUT's bytes into OUTPUT as `static const char VARIABLE[] = {...};` (NUL-terminated).
# Hex bytes rather than a raw string literal: no length limit and no delimiter clashes.
file(READ ${INPUT} content HEX)
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${content}")
file(WRITE ${OUTPUT}.tmp "/* generated from ${INPUT} */\nstatic const char ${VARIABLE}[] = {${bytes}0x00};\n")
file(RENAME ${OUTPUT}.tmp ${OUTPUT})
