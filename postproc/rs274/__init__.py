"""The RS274 family base: what Fanuc, LinuxCNC and their relatives share."""
