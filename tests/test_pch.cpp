// The translation unit that builds tests/test_pch.h once for the tests that share its flags.
