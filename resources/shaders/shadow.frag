#version 330 core
// Shadow depth pass: depth only.
void main() {}
