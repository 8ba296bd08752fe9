SCAN_TOPIC = '/fleet/scan'
