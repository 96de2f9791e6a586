float secret() { return 42.0; }
