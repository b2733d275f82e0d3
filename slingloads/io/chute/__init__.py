"""Input and output of the drogue-parachute sizing: its Study parameters and sheet, the
reader, the Excel/CSV report and the plots."""
