set(analysis_cases
  help wedge_v4 wedge_v5 newmark_v3 sliding3d_v3 sliding3d_v4 sliding3d_record
  backfit_segments record_process bad_records bad_arguments compare_v3 earthquake_errors
  spectra_record spectra_table spectra_results spectra_errors)
