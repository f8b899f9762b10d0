#!/usr/bin/python3
"""The peer matrix of ../peers_final with the ES and SMS-EMOA rerun with the jog move on
(configs/es_jog.yaml; run.sh here): the peers' arms as ../peers_final/compare.py reads them, this
folder's ES and SMS-EMOA read last, so they replace the earlier arms.

Usage: /usr/bin/python3 experiments/optimize/peers_jog/compare.py   (writes compare.md here)
"""
import importlib.util
import os

here = os.path.dirname(os.path.abspath(__file__))
spec = importlib.util.spec_from_file_location("final", os.path.join(here, "..", "peers_final", "compare.py"))
final = importlib.util.module_from_spec(spec)
spec.loader.exec_module(final)

final.write("# The ES and SMS-EMOA with the jog move against every peer, 11 seeds",
            "experiments/optimize/peers_jog/compare.py", os.path.join(here, "compare.md"),
            lambda mold, budget: [os.path.join(here, f"results_{mold}_{budget}_{a}.csv") for a in ["es", "sms-emoa"]])
