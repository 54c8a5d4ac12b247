__version__ = "0.1.0"
__release_date__ = "2026-11-22"  # ISO date of this version; the SimReady usd_date_generated unless SOURCE_DATE_EPOCH
