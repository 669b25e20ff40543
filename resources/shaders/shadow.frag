// Shadow depth pass: depth only.
void main() {}
