#version 450 core
// Writes the injected defines VALUE_INT and VALUE_FLOAT into an SSBO; fails to compile without them.
#ifndef VALUE_INT
#error VALUE_INT is not defined
#endif

layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Result { int valueInt; float valueFloat; int flagSet; };

void main() {
    valueInt = VALUE_INT;
    valueFloat = VALUE_FLOAT;
#ifdef FLAG
    flagSet = 1;
#else
    flagSet = 0;
#endif
}
