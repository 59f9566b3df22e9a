using OperatorPanel.Core.Cpu;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>What a step checks against: the CPU chosen in step 1 and the symbols earlier steps already use.</summary>
internal sealed record WizardContext(CpuProfile Cpu, IReadOnlySet<string> EarlierSymbols);
