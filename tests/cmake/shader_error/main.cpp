int shaderErrorCheck() {
  return 0;
}
