using OperatorPanel.Core.Cpu;
using OperatorPanel.Core.Transport;

namespace OperatorPanel.ViewModels.Wizard;

/// <summary>
/// What a step checks against: the CPU chosen in step 1, the symbols earlier steps already use, and the link protocol
/// of step 5, which decides the areas the station's cells may name (PPI reads S, AIW, AQW, T and C; Freeport does not).
/// </summary>
internal sealed record WizardContext(CpuProfile Cpu, IReadOnlySet<string> EarlierSymbols, LinkProtocol Link = LinkProtocol.Freeport);
