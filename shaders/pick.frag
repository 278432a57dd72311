#version 330 core
// SPDX-License-Identifier: MIT
// Writes the column id into the integer target: exact, no blending or rounding.
flat in uint columnId;
out uint pickedId;

void main() { pickedId = columnId; }
