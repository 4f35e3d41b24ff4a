; Empty command with comment
(Another empty command with comment)

G0 ; Command with comment
G1 (Another command with comment)
