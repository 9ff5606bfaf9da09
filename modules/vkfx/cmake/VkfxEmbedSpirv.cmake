# cmake -DSPIRV=<file.spv> -DOUTPUT=<file.spv.inc> -DSYMBOL=<name> -P VkfxEmbedSpirv.cmake
#
# Writes a SPIR-V binary as the C array vkfx_embed_shaders() headers include:
# `const uint32_t <SYMBOL>[] = { 0x07230203, ... };`, its little-endian words in order.
foreach(argument SPIRV OUTPUT SYMBOL)
  if(NOT DEFINED ${argument})
    message(FATAL_ERROR "VkfxEmbedSpirv.cmake: -D${argument}= is required")
  endif()
endforeach()
file(READ "${SPIRV}" bytes HEX)
string(LENGTH "${bytes}" digits)
math(EXPR remainder "${digits} % 8")
if(digits EQUAL 0 OR NOT remainder EQUAL 0)
  message(FATAL_ERROR "${SPIRV}: not SPIR-V (${digits} hex digits, not whole 32-bit words)")
endif()
# Each word's four bytes, least significant first in the file, as one 0x literal; eight a line.
string(REGEX REPLACE "(..)(..)(..)(..)" "0x\\4\\3\\2\\1," words "${bytes}")
set(word "0x........,")
string(REGEX REPLACE "(${word}${word}${word}${word}${word}${word}${word}${word})" "\\1\n  " words
                     "${words}")
file(WRITE "${OUTPUT}" "const uint32_t ${SYMBOL}[] = {\n  ${words}\n};\n")
