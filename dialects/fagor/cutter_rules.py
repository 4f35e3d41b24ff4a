"""The Fagor 8070's cutter radius compensation, as far as its manual's text says it: why it is not simulated
(``Fagor.CUTTER_RULES`` stays None; ``Fagor.CUTTER_RULES_LACK`` says why in the verify report), so that a ``G41``/``G42``
towards or from the 8070 is compared as a setting, not as a path (docs/verify.md). Researched for issue 26
(tool26); tags as in DIALECTS.md. ISG's, researched alike: ``dialects/isg/cutter_rules.py``.

Programming manual REF 1709, chapter 13.1 "Tool radius compensation" (easymanua.ls pages 249-259,
the stored text):

* [V] where the angle between two paths is 180 degrees or less, the start, the transition and the cancel do not
  depend on G136/G137 or G138/G139; above 180 degrees they depend on "the type of beginning (G138/G139)", "the type
  of ending (G138/G139)" and "the type of transition (G136/G137)" (13.1.4 "Sections of tool radius compensation").
* [K] G136 joins the compensated paths with an arc, G137 with straight lines; G138 starts and ends the
  compensation directly, G139 indirectly (the tables' column heads: G139 with G136 or G137, G138 alone).
* [?] every construction (start, corner, cancel) is a figure without text in the stored pages, and which of
  G136/G137 and G138/G139 the machine starts in is an OEM parameter not read here.
"""
