# tests for the audit layer (readers, checks, `dualhex audit`)
dualhex_add_test(test_audit_readers SOURCES test_audit_readers.cpp DEPS dualhex::audit dualhex::geometry)
dualhex_add_test(test_audit_checks SOURCES test_audit_checks.cpp DEPS dualhex::audit dualhex::geometry)
