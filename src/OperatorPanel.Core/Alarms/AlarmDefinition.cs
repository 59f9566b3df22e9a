using OperatorPanel.Core.Addressing;

namespace OperatorPanel.Core.Alarms;

/// <summary>
/// A message shown while a flag bit in the PLC is set (seed 000 §7, wizard step 4: "texts of messages, which will be
/// displayed when activation of an appropriate marker in the PLC memory is detected").
/// </summary>
/// <param name="Flag">The marker bit, usually M or V; a bit the link serves.</param>
/// <param name="Text">The message; never empty.</param>
/// <param name="Class">How serious the alarm is.</param>
/// <param name="AcknowledgementRequired">True when the message stays until the operator acknowledges it.</param>
public sealed record AlarmDefinition(PlcAddress Flag, string Text, AlarmClass Class, bool AcknowledgementRequired);
