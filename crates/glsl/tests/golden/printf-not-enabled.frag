// Without the extension a string is an error and debugPrintfEXT an
// ordinary (here undeclared) name.
void main()
{
    debugPrintfEXT("x\n");
    gl_FragColor = vec4(1.0);
}
