using OperatorPanel.Core.Projects;

namespace OperatorPanel.ViewModels.Inputs;

/// <summary>An input lamp: read only.</summary>
public sealed class LampViewModel(ProjectStation station, IoSymbol symbol) : IoPointViewModel(station, symbol);
