"""Set-up bases shipped with postproc, named by file in ``extends`` (``postproc.setup.load.BASES``)."""
