#version 330 core
// Writes the column id into the integer target: exact, no blending or rounding.
flat in uint columnId;
out uint pickedId;

void main() { pickedId = columnId; }
