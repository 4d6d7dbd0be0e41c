"""bench.operator: the console operator re-asks until the manometer reading is a pressure."""

from mkm.bench.operator import ConsoleOperator


def test_console_operator_reasks_on_bad_readings(capsys):
    answers = iter(["", "one bar", "-0.1", "1.05"])
    prompts = []

    def ask(prompt):
        prompts.append(prompt)
        return next(answers)

    assert ConsoleOperator(ask).set_pressure(1.0) == 1.05
    assert len(prompts) == 4 and "Set the regulator to 1 bar" in prompts[0]
    out = capsys.readouterr().out
    assert "'one bar' is not a number" in out and "is negative" in out


def test_console_operator_vent_and_masses():
    prompts = []
    operator = ConsoleOperator(lambda p: prompts.append(p) or "0.02")
    assert operator.vent() == 0.02  # the reading that confirms the vent
    operator.hang_mass(2.5)
    operator.hang_mass(0.0)
    assert "VENT" in prompts[0] and "Hang 2.5 kg" in prompts[1] and "Unload" in prompts[2]
