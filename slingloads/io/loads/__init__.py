"""Input and output of the structural loads analysis: its Study parameters and sheets, the
reader that builds the loads study, the Excel/CSV report and the plots."""
