edgefit_add_test(report_test SOURCES report/table_test.cc report/chart_test.cc
                 report/world_report_test.cc
                 LIBS edgefit::report)
