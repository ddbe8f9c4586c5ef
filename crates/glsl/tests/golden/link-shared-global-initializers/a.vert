float scale = 2.0;
float scaled(float x) { return x * scale; }
