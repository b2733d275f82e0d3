"""Input and output of the lateral-step pendulum study: its Study parameters and sheets, the
reader, the Excel report and the plots."""
