# SPDX-License-Identifier: Apache-2.0
# Writes INPUT's bytes into OUTPUT as `static const char VARIABLE[] = {...};` (NUL-terminated),
# plus `static const char VARIABLE_path[]`, INPUT's absolute path. Hex bytes rather than a raw
# string literal: no length limit and no delimiter clashes.
file(READ ${INPUT} content HEX)
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${content}")
string(REPLACE "\\" "\\\\" path_literal "${INPUT}")
string(REPLACE "\"" "\\\"" path_literal "${path_literal}")
file(WRITE ${OUTPUT}.tmp "/* generated from ${INPUT} */\n"
     "static const char ${VARIABLE}[] = {${bytes}0x00};\n"
     "static const char ${VARIABLE}_path[] = \"${path_literal}\";\n")
file(RENAME ${OUTPUT}.tmp ${OUTPUT})
