namespace OperatorPanel.Core.Ppi;

/// <summary>Where an address's bytes are in a plan's answers: job <see cref="Request"/>, its item <see cref="Item"/>, from byte <see cref="Offset"/>.</summary>
public readonly record struct PpiSlice(int Request, int Item, int Offset, int Length);
